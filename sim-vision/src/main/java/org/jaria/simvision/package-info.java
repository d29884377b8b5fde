/**
 * The simulator's camera seen by ACTS: {@link org.jaria.simvision.SimCameraSource} hands the
 * simulated camera's frames to the colour tracker as any camera's, {@link
 * org.jaria.simvision.SimCameraPtz} points it like the robot's pan-tilt unit, and the scenes
 * ({@link org.jaria.simvision.TrainingScene}, {@link org.jaria.simvision.ChaseScene}) set up worlds
 * with coloured objects and the channels trained on them, for EZ-Train, the simulator view and the
 * chase demo.
 */
package org.jaria.simvision;
