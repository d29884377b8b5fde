/**
 * The Monte Carlo localization filter: {@link org.jaria.arnl.mcl.MclFilter} (particles in primitive
 * arrays, low-variance and KLD resampling), {@link org.jaria.arnl.mcl.MotionModel} (odometry noise
 * whose variance grows with the motion), {@link org.jaria.arnl.mcl.LikelihoodField} and {@link
 * org.jaria.arnl.mcl.SonarScan} (the sonar model: each echo tested across its cone against a
 * precomputed distance field).
 */
package org.jaria.arnl.mcl;
