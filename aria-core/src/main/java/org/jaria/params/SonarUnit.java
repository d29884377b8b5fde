package org.jaria.params;

/**
 * One sonar transducer from a {@code SonarUnit} line: where it sits on the robot and which way it
 * faces. Positions are mm from the robot's centre of rotation (x forward, y left), the heading in
 * degrees counter-clockwise from straight ahead.
 *
 * <p>Classic Pioneer lines have four numbers ({@code SonarUnit <n> <x> <y> <th>}); lines for robots
 * with MTX sonar boards add the board, the unit's position on that board and optionally gain,
 * detection threshold, maximum range and whether autonomous driving may use the sonar. The MTX
 * fields are 0 (and {@code useForAutonomousDriving} true) for classic lines.
 *
 * @param number the sonar's index (0-based, as in the SIP)
 * @param x x position, mm
 * @param y y position, mm
 * @param th heading, degrees
 * @param mtxBoard MTX sonar board (1-based), 0 if none
 * @param mtxBoardUnit position of the unit on its MTX board (1-based), 0 if none
 * @param mtxGain MTX gain, 0 for the board default
 * @param mtxDetectionThreshold MTX detection threshold, 0 for the board default
 * @param mtxMaxRange MTX maximum range, 0 for the board default
 * @param useForAutonomousDriving whether obstacle avoidance should use this sonar
 */
public record SonarUnit(
    int number,
    int x,
    int y,
    int th,
    int mtxBoard,
    int mtxBoardUnit,
    int mtxGain,
    int mtxDetectionThreshold,
    int mtxMaxRange,
    boolean useForAutonomousDriving) {

  /** A classic (non-MTX) sonar unit. */
  public SonarUnit(int number, int x, int y, int th) {
    this(number, x, y, th, 0, 0, 0, 0, 0, true);
  }
}
