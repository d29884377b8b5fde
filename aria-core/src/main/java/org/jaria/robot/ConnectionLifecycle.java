package org.jaria.robot;

import java.nio.file.Path;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.protocol.packets.ArConfigPacket;

/**
 * Connecting to the robot and losing it: ARIA's {@code setDeviceConnection}, {@code
 * blockingConnect}, {@code disconnect}, what the handshake learnt (name, type, CONFIGpac), the
 * connection timeout, and the callbacks that run when a connection is made, fails or ends.
 *
 * <p>{@link ArRobot} is the only implementation: this interface keeps one job of ARIA's large
 * {@code ArRobot} API in a file of its own, and hands every call to the robot's link (which owns
 * the connection, the handshake and the timeouts).
 */
public sealed interface ConnectionLifecycle permits ArRobot {

  /** Sets the connection to the robot (TCP, serial or pipe); it is opened when connecting. */
  default void setDeviceConnection(ArDeviceConnection c) {
    link().setDeviceConnection(c);
  }

  /** The connection to the robot, or null. */
  default ArDeviceConnection getDeviceConnection() {
    return link().getDeviceConnection();
  }

  /**
   * Connects to the robot, waiting until connected or failed (a few seconds at most). If the
   * robot's cycle is already running on another thread, the connection is made there and this
   * method waits for it.
   *
   * @return whether the robot is connected
   */
  default boolean blockingConnect() {
    return link().blockingConnect();
  }

  /**
   * Starts connecting without waiting: the running cycle (or the next {@link ArRobot#loopOnce}
   * calls) carry the handshake forward. Watch {@link #isConnected()} or add a connect callback.
   *
   * @return false if there is no connection to use
   */
  default boolean asyncConnect() {
    return link().asyncConnect();
  }

  /** Whether the robot is connected. */
  default boolean isConnected() {
    return link().isConnected();
  }

  /** Whether a connection attempt is under way. */
  default boolean isConnecting() {
    return link().isConnecting();
  }

  /** Why the last connection attempt failed, or an empty string. */
  default String getConnectFailure() {
    return link().failure();
  }

  /** Sends CLOSE and closes the connection; the disconnect-normally callbacks run. */
  default boolean disconnect() {
    return link().disconnect();
  }

  /** The robot's name from the handshake. */
  default String getRobotName() {
    return link().robotName();
  }

  /** The robot's type from the handshake, e.g. "Pioneer". */
  default String getRobotType() {
    return link().robotType();
  }

  /** The robot's subtype from the handshake, lower-cased, e.g. "p3dx-sh". */
  default String getRobotSubType() {
    return link().robotSubType();
  }

  /** The CONFIGpac received when connecting, or null. */
  default ArConfigPacket getOrigRobotConfig() {
    return link().config();
  }

  /**
   * Where user parameter files ({@code <subtype>.p}, {@code <name>.p}) are looked for; by default
   * {@code $JARIA_PARAMS}, else {@code ~/.jaria/params}. Null uses only the bundled files.
   */
  default void setParamsDirectory(Path dir) {
    link().setParamsDirectory(dir);
  }

  /** Where user parameter files are looked for (see {@link #setParamsDirectory}); may be null. */
  default Path getParamsDirectory() {
    return link().paramsDirectory();
  }

  /**
   * How long without any packet before the connection counts as lost, ms (default 8000; 0 never).
   */
  default void setConnectionTimeoutTime(long ms) {
    link().setTimeoutMs(ms);
  }

  /** The connection-lost timeout, ms. */
  default long getConnectionTimeoutTime() {
    return link().timeoutMs();
  }

  /** Runs when a connection is made. */
  default void addConnectCB(Runnable cb) {
    link().connectCBs.add(cb);
  }

  /** Removes a connect callback. */
  default void remConnectCB(Runnable cb) {
    link().connectCBs.remove(cb);
  }

  /** Runs when a connection attempt fails. */
  default void addFailedConnectCB(Runnable cb) {
    link().failedConnectCBs.add(cb);
  }

  /** Removes a failed-connect callback. */
  default void remFailedConnectCB(Runnable cb) {
    link().failedConnectCBs.remove(cb);
  }

  /** Runs when the program disconnects on purpose. */
  default void addDisconnectNormallyCB(Runnable cb) {
    link().disconnectNormallyCBs.add(cb);
  }

  /** Removes a disconnect-normally callback. */
  default void remDisconnectNormallyCB(Runnable cb) {
    link().disconnectNormallyCBs.remove(cb);
  }

  /** Runs when the connection is lost (no packets, broken link, controller reset). */
  default void addDisconnectOnErrorCB(Runnable cb) {
    link().disconnectOnErrorCBs.add(cb);
  }

  /** Removes a disconnect-on-error callback. */
  default void remDisconnectOnErrorCB(Runnable cb) {
    link().disconnectOnErrorCBs.remove(cb);
  }

  /**
   * The robot's link. Java has no package-private interface members, so it is reached through the
   * only implementation.
   */
  private RobotLink link() {
    return ((ArRobot) this).link;
  }
}
