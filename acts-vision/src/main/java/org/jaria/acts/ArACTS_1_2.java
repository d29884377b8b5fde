package org.jaria.acts;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.util.concurrent.TimeUnit;
import org.jaria.clock.Clock;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.connection.ArTcpConnection;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The client of an ACTS colour-tracking server (ARIA's {@code ArACTS_1_2}), with ARIA's method
 * names so that programs such as the thesis's {@code actsColorFollowingExample} port line by line:
 *
 * <pre>{@code
 * ArACTS_1_2 acts = new ArACTS_1_2();
 * acts.openPort("localhost", 5001);
 * acts.requestPacket();
 * if (acts.receiveBlobInfo()) {
 *   ArACTSBlob blob = new ArACTSBlob();
 *   for (int i = 1; i <= acts.getNumBlobs(1); i++) {
 *     acts.getBlob(1, i, blob);
 *   }
 * }
 * }</pre>
 *
 * <p>ARIA's {@code openPort(ArRobot*, host, port)} also hooks the client into the robot's sensor
 * cycle; here {@link #openPort(String, int)} only connects, and {@link #actsHandler()} is the
 * method such a hook calls every cycle (a robot-driven variant will be added with the robot glue).
 * The wire protocol is described in {@link ActsProtocol}.
 *
 * <p>Differences from ARIA, all in the direction of robustness: a reply that arrives in pieces
 * slower than the read timeouts is not lost — the next {@link #receiveBlobInfo()} call continues
 * where the last one stopped; a reply with bytes that are not valid digits, or counts that do not
 * add up, is rejected (counted in {@link #getProtocolErrors()}) instead of being decoded into
 * nonsense; and {@link #invert(int, int)} really stores the size it is given.
 *
 * <p>Like ARIA's class, an instance is meant to be used from one thread.
 */
public class ArACTS_1_2 implements AutoCloseable {

  /** Number of channels. */
  public static final int NUM_CHANNELS = ActsProtocol.NUM_CHANNELS;

  /** Most blobs per channel. */
  public static final int MAX_BLOBS = ActsProtocol.MAX_BLOBS;

  /** Bytes per blob on the wire. */
  public static final int ACTS_BLOB_DATA_SIZE = ActsProtocol.BLOB_SIZE;

  /** Bytes of the reply header. */
  public static final int DATA_HEADER = ActsProtocol.HEADER_SIZE;

  /** ARIA's receive buffer size; no valid reply is longer. */
  public static final int MAX_DATA = 5300;

  private static final Logger LOG = LoggerFactory.getLogger(ArACTS_1_2.class);
  private static final int CONNECT_TIMEOUT_MS = 3000;

  private final Clock clock;
  private ArDeviceConnection conn;
  private String openMessage = "";

  // Reply being received.
  private final byte[] rx = new byte[MAX_DATA];
  private int have;
  private int need = DATA_HEADER;
  private final int[] rxIndex = new int[NUM_CHANNELS];
  private final int[] rxNum = new int[NUM_CHANNELS];

  // Last complete reply.
  private final byte[] data = new byte[MAX_DATA];
  private final int[] blobIndex = new int[NUM_CHANNELS];
  private final int[] blobNum = new int[NUM_CHANNELS];
  private boolean blobsBad = true;
  private boolean requested;
  private long protocolErrors;

  private int headerTimeoutMs = 20;
  private int blobTimeoutMs = 10;
  private boolean inverted;
  private int width = 160;
  private int height = 120;

  /** A client timed by the system clock (not yet connected). */
  public ArACTS_1_2() {
    this(Clock.system());
  }

  /** A client whose read timeouts run on {@code clock}. */
  public ArACTS_1_2(Clock clock) {
    this.clock = clock;
  }

  // ---------------------------------------------------------------- connection

  /** Connects to ACTS on this machine, port 5001. */
  public boolean openPort() {
    return openPort("localhost", ActsProtocol.DEFAULT_PORT);
  }

  /** Connects to ACTS on {@code host}, port 5001. */
  public boolean openPort(String host) {
    return openPort(host, ActsProtocol.DEFAULT_PORT);
  }

  /**
   * Connects to the ACTS server at {@code host:port}.
   *
   * @return whether the connection was made; if not, {@link #getOpenMessage()} says why
   */
  public boolean openPort(String host, int port) {
    closePort();
    Socket s = new Socket();
    try {
      s.connect(new InetSocketAddress(host, port), CONNECT_TIMEOUT_MS);
      return openPort(ArTcpConnection.wrap(s, clock));
    } catch (IOException e) {
      try {
        s.close();
      } catch (IOException ignored) {
        // nothing more to release
      }
      openMessage =
          "could not connect to ACTS at "
              + host
              + ":"
              + port
              + " ("
              + e.getMessage()
              + "); start the server with './jaria acts' (or ACTS itself) and check the host and"
              + " port";
      LOG.warn("ArACTS_1_2: {}", openMessage);
      return false;
    }
  }

  /**
   * Uses an already made connection (opened here if it is not yet): a TCP connection, or an
   * in-memory pipe in tests.
   */
  public boolean openPort(ArDeviceConnection connection) {
    closePort();
    try {
      if (connection.getStatus() != ArDeviceConnection.Status.OPEN) {
        connection.open();
      }
    } catch (IOException e) {
      openMessage = "could not open " + connection.getPortName() + ": " + e.getMessage();
      LOG.warn("ArACTS_1_2: {}", openMessage);
      return false;
    }
    conn = connection;
    openMessage = "";
    requested = false;
    resetReceive();
    blobsBad = true;
    return true;
  }

  /**
   * ARIA's {@code openPort(ArRobot*)}: connects to ACTS on this machine (port 5001) and has the
   * robot run {@link #actsHandler()} every cycle, so {@link #getNumBlobs} and {@link #getBlob}
   * always hold the latest frame's blobs when actions fire.
   */
  public boolean openPort(org.jaria.robot.ArRobot robot) {
    return openPort(robot, "localhost", ActsProtocol.DEFAULT_PORT);
  }

  /** As {@link #openPort(org.jaria.robot.ArRobot)}, to ACTS at {@code host:port}. */
  public boolean openPort(org.jaria.robot.ArRobot robot, String host, int port) {
    return openPort(host, port) && attach(robot);
  }

  /**
   * As {@link #openPort(org.jaria.robot.ArRobot)}, over a connection you made (an in-memory pipe in
   * lockstep tests, where reads must not wait: use {@code setReadTimeouts(0, 0)}).
   */
  public boolean openPort(org.jaria.robot.ArRobot robot, ArDeviceConnection connection) {
    return openPort(connection) && attach(robot);
  }

  private boolean attach(org.jaria.robot.ArRobot robot) {
    // Before the actions (position 50+ are range devices): blobs are fresh when actions fire.
    robot.addSensorInterpTask("ACTS", 60, this::actsHandler);
    return true;
  }

  /** Why the last {@code openPort} failed, or an empty string. */
  public String getOpenMessage() {
    return openMessage;
  }

  /** Closes the connection to ACTS. */
  public boolean closePort() {
    ArDeviceConnection c = conn;
    conn = null;
    if (c != null) {
      c.close();
    }
    return true;
  }

  /** Same as {@link #closePort()}. */
  @Override
  public void close() {
    closePort();
  }

  /** Whether the connection to ACTS is open. */
  public boolean isConnected() {
    return conn != null && conn.getStatus() == ArDeviceConnection.Status.OPEN;
  }

  // ---------------------------------------------------------------- requests

  /** Asks ACTS for the current blob data (sends {@code '0'}). */
  public boolean requestPacket() {
    return send(ActsProtocol.REQUEST_PACKET, "requestPacket");
  }

  /** Asks ACTS to quit (sends {@code '1'}). */
  public boolean requestQuit() {
    return send(ActsProtocol.REQUEST_QUIT, "requestQuit");
  }

  private boolean send(byte b, String what) {
    if (!isConnected()) {
      LOG.debug("ArACTS_1_2::{}: no connection to ACTS", what);
      return false;
    }
    try {
      conn.write(new byte[] {b}, 0, 1);
      return true;
    } catch (IOException e) {
      LOG.debug("ArACTS_1_2::{}: {}", what, e.getMessage());
      return false;
    }
  }

  /**
   * Reads the reply to a {@link #requestPacket()}: waits up to the header timeout (20 ms, like
   * ARIA) for the header and up to the blob timeout (10 ms) for the blob data. If the reply is not
   * complete by then, returns false and keeps what arrived; the next call continues.
   *
   * @return whether a complete, valid reply was received (the blobs can then be read)
   */
  public boolean receiveBlobInfo() {
    blobsBad = true;
    if (!isConnected()) {
      LOG.debug("ArACTS_1_2::receiveBlobInfo: no connection to ACTS");
      return false;
    }
    try {
      if (have < DATA_HEADER) {
        fill(DATA_HEADER, headerTimeoutMs);
        if (have < DATA_HEADER) {
          return false;
        }
        if (!parseHeader()) {
          return false;
        }
      }
      if (have < need) {
        fill(need, blobTimeoutMs);
        if (have < need) {
          return false;
        }
      }
      if (!checkBlobDigits()) {
        return false;
      }
    } catch (IOException e) {
      LOG.debug("ArACTS_1_2::receiveBlobInfo: {}", e.getMessage());
      return false;
    }
    System.arraycopy(rx, 0, data, 0, need);
    System.arraycopy(rxIndex, 0, blobIndex, 0, NUM_CHANNELS);
    System.arraycopy(rxNum, 0, blobNum, 0, NUM_CHANNELS);
    resetReceive();
    blobsBad = false;
    return true;
  }

  private void fill(int target, int timeoutMs) throws IOException {
    long deadline = clock.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
    while (have < target) {
      long left = TimeUnit.NANOSECONDS.toMillis(deadline - clock.nanoTime());
      int n = conn.read(rx, have, target - have, Math.max(0, left));
      if (n < 0) {
        throw new IOException("ACTS closed the connection");
      }
      have += n;
      if (n == 0 && left <= 0) {
        return;
      }
    }
  }

  private boolean parseHeader() throws IOException {
    int total = 0;
    for (int i = 0; i < NUM_CHANNELS; i++) {
      int index = ActsProtocol.getNumber(rx, i * 4, 2);
      int num = ActsProtocol.getNumber(rx, i * 4 + 2, 2);
      if (index < 0 || num < 0) {
        return reject("header byte is not a base-64 digit (+1)");
      }
      if (num > MAX_BLOBS) {
        return reject("channel " + (i + 1) + " claims " + num + " blobs (at most 10)");
      }
      rxIndex[i] = index;
      rxNum[i] = num;
      total += num;
    }
    for (int i = 0; i < NUM_CHANNELS; i++) {
      if (rxNum[i] > 0 && rxIndex[i] + rxNum[i] > total) {
        return reject("channel " + (i + 1) + " points past the " + total + " blobs sent");
      }
    }
    need = DATA_HEADER + total * ACTS_BLOB_DATA_SIZE;
    return true;
  }

  private boolean checkBlobDigits() throws IOException {
    for (int i = DATA_HEADER; i < need; i++) {
      int d = rx[i] & 0xFF;
      if (d < 1 || d > 64) {
        return reject("blob byte " + (i - DATA_HEADER) + " is not a base-64 digit (+1)");
      }
    }
    return true;
  }

  // A malformed reply leaves the stream position unknown: drop what is buffered and start over.
  private boolean reject(String why) throws IOException {
    protocolErrors++;
    LOG.warn("ArACTS_1_2: bad reply from ACTS ({}); discarding it", why);
    resetReceive();
    while (conn.read(rx, 0, rx.length, 0) > 0) {
      // drain
    }
    requested = false;
    return false;
  }

  private void resetReceive() {
    have = 0;
    need = DATA_HEADER;
  }

  /**
   * ARIA's per-cycle handler: if no request is outstanding, or the outstanding one has been
   * answered, requests the next packet. Call it every robot cycle (about every 100 ms).
   */
  public void actsHandler() {
    if (!requested || receiveBlobInfo()) {
      requested = true;
      requestPacket();
    }
  }

  /** Sets how long {@link #receiveBlobInfo()} waits for the header and for the blob data. */
  public void setReadTimeouts(int headerMs, int blobMs) {
    if (headerMs < 0 || blobMs < 0) {
      throw new IllegalArgumentException("timeouts must be >= 0 ms");
    }
    headerTimeoutMs = headerMs;
    blobTimeoutMs = blobMs;
  }

  /** How many malformed replies were rejected. */
  public long getProtocolErrors() {
    return protocolErrors;
  }

  // ---------------------------------------------------------------- blobs

  /**
   * The number of blobs on a channel in the last complete reply.
   *
   * @param channel 1..32
   * @return the count, 0 before the first reply, or -1 if the channel is out of range (like ARIA)
   */
  public int getNumBlobs(int channel) {
    if (channel < 1 || channel > NUM_CHANNELS) {
      return -1;
    }
    return blobNum[channel - 1];
  }

  /**
   * Fills {@code blob} with blob {@code blobNumber} (1..count, largest first) of a channel.
   *
   * @return false if there is no valid data or the numbers are out of range (like ARIA)
   */
  public boolean getBlob(int channel, int blobNumber, ArACTSBlob blob) {
    if (blobsBad) {
      LOG.debug("ArACTS_1_2::getBlob: there is no valid blob data");
      return false;
    }
    if (channel < 1 || channel > NUM_CHANNELS) {
      LOG.info("ArACTS_1_2::getBlob: channel {} out of range 1 to {}", channel, NUM_CHANNELS);
      return false;
    }
    int c = channel - 1;
    if (blobNumber < 1 || blobNumber > blobNum[c]) {
      LOG.info("ArACTS_1_2::getBlob: blob number {} out of range 1 to {}", blobNumber, blobNum[c]);
      return false;
    }
    int off = DATA_HEADER + (blobIndex[c] + blobNumber - 1) * ACTS_BLOB_DATA_SIZE;
    blob.setArea(ActsProtocol.getNumber(data, off, 4));
    blob.setXCG(invertX(ActsProtocol.getNumber(data, off + 4, 2)));
    blob.setYCG(invertY(ActsProtocol.getNumber(data, off + 6, 2)));
    blob.setLeft(invertX(ActsProtocol.getNumber(data, off + 8, 2)));
    blob.setRight(invertX(ActsProtocol.getNumber(data, off + 10, 2)));
    blob.setTop(invertY(ActsProtocol.getNumber(data, off + 12, 2)));
    blob.setBottom(invertY(ActsProtocol.getNumber(data, off + 14, 2)));
    return true;
  }

  /**
   * Flips the blob coordinates for a camera mounted upside down: from now on x becomes {@code width
   * - x} and y becomes {@code height - y} (ARIA's formula, kept so ported programs see the same
   * numbers; left and right, and top and bottom, are flipped but not swapped). ACTS does not tell
   * the client the image size, so give it (ARIA's default is 160 × 120).
   */
  public void invert(int width, int height) {
    if (width < 1 || height < 1) {
      throw new IllegalArgumentException("image size must be positive");
    }
    inverted = true;
    this.width = width;
    this.height = height;
  }

  /** {@link #invert(int, int)} for ACTS's default 160 × 120 image. */
  public void invert() {
    invert(160, 120);
  }

  private int invertX(int x) {
    return inverted ? width - x : x;
  }

  private int invertY(int y) {
    return inverted ? height - y : y;
  }
}
