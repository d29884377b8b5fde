package org.jaria.connection;

import com.fazecast.jSerialComm.SerialPort;
import java.io.IOException;
import org.jaria.clock.Clock;

/**
 * A serial-port connection through jSerialComm (ARIA's {@code ArSerialConnection}): 8 data bits, no
 * parity, one stop bit, no flow control, as a Pioneer's HOST port expects.
 *
 * <p>The port is locked for exclusive use while open, so a second program cannot open it and steal
 * half of the robot's bytes; the lock goes away on {@link #close()}.
 */
public final class ArSerialConnection implements ArDeviceConnection {

  /** ARIA's default port on Linux. */
  public static final String DEFAULT_PORT = "/dev/ttyS0";

  /** ARCOS's baud rate at power-up. */
  public static final int DEFAULT_BAUD = 9600;

  private final String portName;
  private final Clock clock;
  private volatile int baud;
  private volatile SerialPort port;
  private volatile Status status = Status.NEVER_OPENED;
  private volatile String openMessage = "";
  private volatile long timeRead;
  private long currentTimeout = -1;

  /** A connection to {@code portName} at 9600 baud (not yet open). */
  public ArSerialConnection(String portName) {
    this(portName, DEFAULT_BAUD, Clock.system());
  }

  /** A connection to {@code portName} (not yet open). */
  public ArSerialConnection(String portName, int baud, Clock clock) {
    this.portName = portName;
    this.baud = baud;
    this.clock = clock;
  }

  @Override
  public synchronized void open() throws IOException {
    if (status == Status.OPEN) {
      return;
    }
    SerialPort p;
    try {
      p = SerialPort.getCommPort(portName);
    } catch (RuntimeException e) {
      // jSerialComm's own message only repeats the name; say how to find the right one.
      throw fail(
          "could not open serial port "
              + portName
              + ": there is no such port (ls /dev/ttyUSB* /dev/ttyACM* /dev/ttyS* lists them;"
              + " on Windows, the Device Manager)");
    }
    p.setComPortParameters(baud, 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY);
    p.setFlowControl(SerialPort.FLOW_CONTROL_DISABLED);
    if (!p.openPort()) {
      int code = p.getLastErrorCode();
      throw fail(
          "could not open serial port "
              + portName
              + " (error "
              + code
              + "): check that it exists, that you may use it (on Linux: sudo usermod -aG"
              + " dialout $USER, then log in again) and that no other program has it open");
    }
    port = p;
    currentTimeout = -1;
    openMessage = "";
    status = Status.OPEN;
  }

  private IOException fail(String message) {
    openMessage = message;
    status = Status.OPEN_FAILED;
    return new IOException(message);
  }

  /**
   * Changes the baud rate, also while open (ARIA switches a robot from 9600 to 38400 after
   * connecting).
   *
   * @return whether the port accepted the rate
   */
  public synchronized boolean setBaud(int newBaud) {
    baud = newBaud;
    SerialPort p = port;
    return p == null || p.setBaudRate(newBaud);
  }

  /** The current baud rate. */
  public int getBaud() {
    return baud;
  }

  @Override
  public Status getStatus() {
    return status;
  }

  @Override
  public String getOpenMessage() {
    return openMessage;
  }

  @Override
  public int read(byte[] buf, int off, int len, long timeoutMs) throws IOException {
    SerialPort p = requireOpen();
    if (timeoutMs <= 0) {
      int avail = p.bytesAvailable();
      if (avail < 0) {
        return lost();
      }
      if (avail == 0) {
        return 0;
      }
      len = Math.min(len, avail);
      timeoutMs = 1;
    }
    if (currentTimeout != timeoutMs) {
      p.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING, (int) timeoutMs, 0);
      currentTimeout = timeoutMs;
    }
    int n = p.readBytes(buf, len, off);
    if (n < 0) {
      return status == Status.OPEN ? lost() : -1;
    }
    if (n > 0) {
      timeRead = clock.nanoTime();
    }
    return n;
  }

  private int lost() throws IOException {
    status = Status.CLOSED_ERROR;
    throw new IOException(
        "serial port " + portName + " stopped working (unplugged?); reconnect the robot");
  }

  @Override
  public void write(byte[] buf, int off, int len) throws IOException {
    SerialPort p = requireOpen();
    int done = 0;
    while (done < len) {
      int n = p.writeBytes(buf, len - done, off + done);
      if (n < 0) {
        lost();
      }
      done += n;
    }
  }

  private SerialPort requireOpen() throws IOException {
    SerialPort p = port;
    if (p == null || status != Status.OPEN) {
      throw new IOException("serial port " + portName + " is not open (status " + status + ")");
    }
    return p;
  }

  @Override
  public synchronized void close() {
    if (status == Status.OPEN) {
      status = Status.CLOSED_NORMALLY;
    }
    SerialPort p = port;
    port = null;
    if (p != null) {
      p.closePort();
    }
  }

  @Override
  public long getTimeRead() {
    return timeRead;
  }

  @Override
  public Clock clock() {
    return clock;
  }

  @Override
  public String getPortName() {
    return "serial " + portName;
  }

  @Override
  public String toString() {
    return getPortName() + " @" + baud + " (" + status + ")";
  }
}
