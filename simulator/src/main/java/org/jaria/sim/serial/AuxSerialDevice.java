package org.jaria.sim.serial;

import java.util.function.Consumer;

/** Something plugged into an auxiliary serial port of a simulated robot (e.g. a PTZ camera). */
public interface AuxSerialDevice {

  /**
   * Takes bytes the client sent to the port, in order, and answers through {@code reply} (zero or
   * more calls, each with the bytes the real device would put on the line).
   */
  void receive(byte[] data, Consumer<byte[]> reply);

  /** A short name for logs, e.g. {@code vcc4}. */
  String name();
}
