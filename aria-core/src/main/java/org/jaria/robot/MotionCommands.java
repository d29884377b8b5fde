package org.jaria.robot;

/**
 * ARIA's motion commands and speed limits: {@code setVel}, {@code setRotVel}, {@code move}, {@code
 * setHeading}, {@code stop} ... and the maxima and accelerations they obey.
 *
 * <p>A motion command is not sent at once: it is kept, takes precedence over the actions, and the
 * robot's cycle sends it (and re-sends it every {@link #getStateReflectionRefreshTime() refresh
 * time}) as ARIA's state reflection does. They may be called from any thread. {@link ArRobot} is
 * the only implementation: this interface keeps one job of ARIA's large {@code ArRobot} API in a
 * file of its own, and hands every call to the robot's state reflector.
 */
public sealed interface MotionCommands permits ArRobot {

  /** Drives at {@code mmPerSec} (negative backwards). */
  default void setVel(double mmPerSec) {
    motion().setVel(mmPerSec);
  }

  /** Drives each wheel at its own speed, mm/s (sent as VEL2, in Vel2Divisor steps). */
  default void setVel2(double leftMmPerSec, double rightMmPerSec) {
    motion().setVel2(leftMmPerSec, rightMmPerSec);
  }

  /** Turns at {@code degPerSec} (+ counter-clockwise). */
  default void setRotVel(double degPerSec) {
    motion().setRotVel(degPerSec);
  }

  /** Turns to the global heading {@code degrees}, the shorter way round. */
  default void setHeading(double degrees) {
    motion().setHeading(degrees);
  }

  /** Turns by {@code degrees} from the current heading (+ counter-clockwise). */
  default void setDeltaHeading(double degrees) {
    motion().setDeltaHeading(degrees);
  }

  /** Drives {@code mm} forward (negative backwards) and stops. */
  default void move(double mm) {
    motion().move(mm);
  }

  /** Whether the last {@link #move} is done, within the move-done distance (default 40 mm). */
  default boolean isMoveDone() {
    return motion().isMoveDone(0);
  }

  /** Whether the last {@link #move} is done within {@code delta} mm. */
  default boolean isMoveDone(double delta) {
    return motion().isMoveDone(delta);
  }

  /** Whether the last heading command is done, within the heading-done difference (3°). */
  default boolean isHeadingDone() {
    return motion().isHeadingDone(0);
  }

  /** Whether the last heading command is done within {@code delta} degrees. */
  default boolean isHeadingDone(double delta) {
    return motion().isHeadingDone(delta);
  }

  /** Sets the default tolerance of {@link #isMoveDone()}, mm. */
  default void setMoveDoneDist(double mm) {
    motion().setMoveDoneDist(mm);
  }

  /** The default tolerance of {@link #isMoveDone()}, mm. */
  default double getMoveDoneDist() {
    return motion().getMoveDoneDist();
  }

  /** Sets the default tolerance of {@link #isHeadingDone()}, degrees. */
  default void setHeadingDoneDiff(double degrees) {
    motion().setHeadingDoneDiff(degrees);
  }

  /** The default tolerance of {@link #isHeadingDone()}, degrees. */
  default double getHeadingDoneDiff() {
    return motion().getHeadingDoneDiff();
  }

  /** Stops translation and rotation now (STOP), and keeps asking for zero speed. */
  default void stop() {
    motion().stop();
  }

  /** Gives the wheels back to the actions: forgets the motion commands. */
  default void clearDirectMotion() {
    motion().clearDirectMotion();
  }

  /** Whether motion commands currently take precedence over actions. */
  default boolean isDirectMotion() {
    return motion().isDirectMotion();
  }

  /**
   * How long a motion command keeps precedence over actions, ms; 0 (the default) means until {@link
   * #clearDirectMotion()}.
   */
  default void setDirectMotionPrecedenceTime(long ms) {
    motion().setDirectMotionPrecedenceTime(ms);
  }

  /** The direct-motion precedence time, ms (0 = until cleared). */
  default long getDirectMotionPrecedenceTime() {
    return motion().getDirectMotionPrecedenceTime();
  }

  /** How often unchanged motion commands are re-sent, ms (default 500). */
  default void setStateReflectionRefreshTime(long ms) {
    motion().setRefreshMillis(ms);
  }

  /** The state-reflection refresh time, ms. */
  default long getStateReflectionRefreshTime() {
    return motion().getRefreshMillis();
  }

  /** Whether the last cycle's commands asked the robot to move. */
  default boolean isTryingToMove() {
    return motion().isTryingToMove();
  }

  // ---------------------------------------------------------------- limits

  /** Maximum translational velocity for motion commands and actions, mm/s. */
  default boolean setTransVelMax(double mmPerSec) {
    return motion().limits().setTransVelMax(mmPerSec);
  }

  /** The maximum translational velocity, mm/s. */
  default double getTransVelMax() {
    return motion().limits().getTransVelMax();
  }

  /** Maximum rotational velocity, deg/s. */
  default boolean setRotVelMax(double degPerSec) {
    return motion().limits().setRotVelMax(degPerSec);
  }

  /** The maximum rotational velocity, deg/s. */
  default double getRotVelMax() {
    return motion().limits().getRotVelMax();
  }

  /** Translational acceleration, mm/s². */
  default void setTransAccel(double a) {
    motion().limits().setTransAccel(a);
  }

  /** The translational acceleration, mm/s². */
  default double getTransAccel() {
    return motion().limits().getTransAccel();
  }

  /** Translational deceleration, mm/s². */
  default void setTransDecel(double a) {
    motion().limits().setTransDecel(a);
  }

  /** The translational deceleration, mm/s². */
  default double getTransDecel() {
    return motion().limits().getTransDecel();
  }

  /** Rotational acceleration, deg/s². */
  default void setRotAccel(double a) {
    motion().limits().setRotAccel(a);
  }

  /** The rotational acceleration, deg/s². */
  default double getRotAccel() {
    return motion().limits().getRotAccel();
  }

  /** Rotational deceleration, deg/s². */
  default void setRotDecel(double a) {
    motion().limits().setRotDecel(a);
  }

  /** The rotational deceleration, deg/s². */
  default double getRotDecel() {
    return motion().limits().getRotDecel();
  }

  /** The top translational velocity this robot allows, mm/s (from CONFIGpac or parameters). */
  default double getAbsoluteMaxTransVel() {
    return motion().limits().getAbsoluteMaxTransVel();
  }

  /** Lowers (or raises) the top translational velocity. */
  default void setAbsoluteMaxTransVel(double mmPerSec) {
    motion().limits().setAbsoluteMaxTransVel(mmPerSec);
  }

  /** The top rotational velocity this robot allows, deg/s. */
  default double getAbsoluteMaxRotVel() {
    return motion().limits().getAbsoluteMaxRotVel();
  }

  /** Lowers (or raises) the top rotational velocity. */
  default void setAbsoluteMaxRotVel(double degPerSec) {
    motion().limits().setAbsoluteMaxRotVel(degPerSec);
  }

  /**
   * The robot's state reflector, which keeps and sends the motion commands. Java has no
   * package-private interface members, so it is reached through the only implementation.
   */
  private StateReflector motion() {
    return ((ArRobot) this).motion;
  }
}
