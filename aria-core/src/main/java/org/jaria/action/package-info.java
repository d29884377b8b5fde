/**
 * Actions: behaviours the robot combines every cycle (ARIA's action system), and ARIA's predefined
 * ones.
 *
 * <p>The framework is {@link org.jaria.action.ArAction}, {@link org.jaria.action.ArActionDesired}
 * and the {@link org.jaria.action.ArPriorityResolver}. The predefined actions keep ARIA's names,
 * parameters and defaults: movement ({@link org.jaria.action.ArActionConstantVelocity}, {@link
 * org.jaria.action.ArActionGoto}, {@link org.jaria.action.ArActionGotoStraight}, {@link
 * org.jaria.action.ArActionDriveDistance}, {@link org.jaria.action.ArActionTurn}, {@link
 * org.jaria.action.ArActionStop}, {@link org.jaria.action.ArActionTriangleDriveTo}), avoidance and
 * recovery ({@link org.jaria.action.ArActionAvoidFront}, {@link
 * org.jaria.action.ArActionAvoidSide}, {@link org.jaria.action.ArActionBumpers}, {@link
 * org.jaria.action.ArActionIRs}, {@link org.jaria.action.ArActionStallRecover}), limiters ({@link
 * org.jaria.action.ArActionLimiterForwards}, {@link org.jaria.action.ArActionLimiterBackwards},
 * {@link org.jaria.action.ArActionLimiterRot}, {@link org.jaria.action.ArActionLimiterTableSensor},
 * {@link org.jaria.action.ArActionDeceleratingLimiter}, {@link
 * org.jaria.action.ArActionMovementParameters}) and input ({@link org.jaria.action.ArActionInput},
 * {@link org.jaria.action.ArActionRatioInput}, {@link org.jaria.action.ArActionKeydrive}, {@link
 * org.jaria.action.ArActionJoydrive}, {@link org.jaria.action.ArActionRobotJoydrive}), plus {@link
 * org.jaria.action.ArActionGroup} and the predefined groups.
 *
 * <p>Where ARIA has a global key or joystick handler, these classes take one as a constructor
 * argument. ARIA's range queries answered −1 when a robot had no range device at all, which made
 * several actions believe an obstacle touched the robot; here "nothing seen" is always a large
 * distance. Other deliberate differences from ARIA are noted on the classes concerned.
 */
package org.jaria.action;
