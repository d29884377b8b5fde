/** The Pioneer gripper ({@link org.jaria.gripper.ArGripper}): paddles and lift. */
package org.jaria.gripper;
