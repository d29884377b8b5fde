/**
 * Path planning: the {@link org.jaria.arnl.plan.CostGrid} (clearance and cost of every cell),
 * {@link org.jaria.arnl.plan.AStarPlanner} and {@link org.jaria.arnl.plan.PathSmoother} (the global
 * plan), {@link org.jaria.arnl.plan.LocalPlanner} (the dynamic window) and {@link
 * org.jaria.arnl.plan.SonarOccupancy} (where the sonar has seen unmapped obstacles).
 */
package org.jaria.arnl.plan;
