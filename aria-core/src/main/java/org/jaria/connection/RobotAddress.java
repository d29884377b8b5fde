package org.jaria.connection;

import java.io.IOException;
import java.util.Locale;
import org.jaria.clock.Clock;

/**
 * Where a robot is, written the way a user types it on a command line: {@code host} or {@code
 * host:port} for a robot (or simulator) reached by TCP, and a serial device for a robot on a serial
 * port: {@code /dev/ttyS0}, {@code /dev/ttyUSB0}, {@code COM3}, optionally with a baud rate after
 * an {@code @} ({@code /dev/ttyS0@115200}). A device path starts with {@code /}; a Windows port is
 * {@code COM} and a number.
 *
 * @param host the TCP host, or null for a serial robot
 * @param port the TCP port (8101 if not given)
 * @param serialPort the serial device, or null for a TCP robot
 * @param baud the serial baud rate (9600 if not given)
 */
public record RobotAddress(String host, int port, String serialPort, int baud) {

  /** Checks. */
  public RobotAddress {
    if ((host == null) == (serialPort == null)) {
      throw new IllegalArgumentException("a robot address is either a TCP host or a serial port");
    }
    if (host != null && (port < 1 || port > 65535)) {
      throw new IllegalArgumentException("TCP port must be 1..65535, got " + port);
    }
    if (serialPort != null && baud <= 0) {
      throw new IllegalArgumentException("baud rate must be positive, got " + baud);
    }
  }

  /**
   * Reads an address as typed.
   *
   * @throws IllegalArgumentException with an example of what is expected
   */
  public static RobotAddress parse(String text) {
    String t = text == null ? "" : text.strip();
    if (t.isEmpty()) {
      throw new IllegalArgumentException(
          "no robot address: give HOST[:PORT] (e.g. localhost:8101) or a serial port (e.g."
              + " /dev/ttyS0)");
    }
    if (t.startsWith("/") || t.toUpperCase(Locale.ROOT).matches("COM\\d+(@.*)?")) {
      int at = t.lastIndexOf('@');
      if (at < 0) {
        return serial(t, ArSerialConnection.DEFAULT_BAUD);
      }
      return serial(t.substring(0, at), number(t.substring(at + 1), "baud rate", text));
    }
    int colon = t.lastIndexOf(':');
    if (colon < 0) {
      return tcp(t, ArTcpConnection.DEFAULT_PORT);
    }
    return tcp(t.substring(0, colon), number(t.substring(colon + 1), "TCP port", text));
  }

  /** A robot reached by TCP. */
  public static RobotAddress tcp(String host, int port) {
    if (host == null || host.isBlank()) {
      throw new IllegalArgumentException("a TCP robot address needs a host name");
    }
    return new RobotAddress(host, port, null, 0);
  }

  /** A robot on a serial port. */
  public static RobotAddress serial(String device, int baud) {
    if (device == null || device.isBlank()) {
      throw new IllegalArgumentException("a serial robot address needs a device");
    }
    return new RobotAddress(null, 0, device, baud);
  }

  private static int number(String s, String what, String text) {
    try {
      return Integer.parseInt(s);
    } catch (NumberFormatException e) {
      throw new IllegalArgumentException(
          "'"
              + text
              + "': the "
              + what
              + " must be a number (e.g. localhost:8101 or /dev/ttyS0@9600)",
          e);
    }
  }

  /** Whether the robot is on a serial port. */
  public boolean isSerial() {
    return serialPort != null;
  }

  /** A connection to the robot, not yet opened. */
  public ArDeviceConnection connection(Clock clock) {
    return isSerial()
        ? new ArSerialConnection(serialPort, baud, clock)
        : new ArTcpConnection(host, port, clock);
  }

  /**
   * Opens a connection to the robot.
   *
   * @param portOption how the user names another port (e.g. "--remote"), for the advice
   * @throws IOException saying what failed and what to try
   */
  public ArDeviceConnection open(Clock clock, String portOption) throws IOException {
    ArDeviceConnection c = connection(clock);
    openExplained(c, portOption);
    return c;
  }

  /**
   * Opens {@code c}; if that fails, the exception's message says what to try: the connection's own
   * reason and advice (a serial port's existence and permission, whether anything listens at a TCP
   * address) and, for a serial port, how to name another one ({@code portOption}).
   */
  public static void openExplained(ArDeviceConnection c, String portOption) throws IOException {
    try {
      c.open();
    } catch (IOException e) {
      String why = e.getMessage() == null ? "could not open " + c.getPortName() : e.getMessage();
      throw new IOException(
          c instanceof ArSerialConnection
              ? why + "; is the robot plugged in and switched on? Another port: " + portOption
              : why,
          e);
    }
  }

  /** ARIA's command-line options for this address ({@code -rh/-rrtp} or {@code -rp/-rb}). */
  public String[] toArgs() {
    return isSerial()
        ? new String[] {"-rp", serialPort, "-rb", String.valueOf(baud)}
        : new String[] {"-rh", host, "-rrtp", String.valueOf(port)};
  }

  @Override
  public String toString() {
    return isSerial() ? serialPort + "@" + baud : host + ":" + port;
  }
}
