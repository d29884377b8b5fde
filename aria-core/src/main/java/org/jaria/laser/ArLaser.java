package org.jaria.laser;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.connection.ArSerialConnection;
import org.jaria.geom.ArPose;
import org.jaria.protocol.DropCounters;
import org.jaria.range.ArRangeDevice;
import org.jaria.range.LaserScan;
import org.jaria.range.LaserScanSource;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A real laser range finder on a serial port or a TCP connection (ARIA's {@code ArLaser}): it
 * connects with {@link #blockingConnect()}, then a reader thread of its own turns the device's
 * scans into range readings (current and cumulative buffers, polar and box queries, as every {@link
 * ArRangeDevice}) and into {@link LaserScan}s for actions that want whole sweeps.
 *
 * <p>If the laser stops sending (unplugged, powered off) for {@link #getConnectionTimeoutMs()}, or
 * its connection fails, the reader stops, {@link #getConnectFailure()} says what happened and the
 * "disconnected on error" callbacks run; calling {@link #blockingConnect()} again reconnects.
 *
 * <p>Readings are taken in the sensor's frame and placed with the robot's pose (if the laser has
 * been added to a robot) plus the laser's mounting pose ({@link #setSensorPosition}); a laser
 * mounted upside down ({@link #setFlipped}) mirrors its angles.
 */
public abstract class ArLaser extends ArRangeDevice implements LaserScanSource, AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(ArLaser.class);

  /** ARIA's default: a laser that sends nothing for this long is taken as lost. */
  public static final long DEFAULT_CONNECTION_TIMEOUT_MS = 3000;

  private final DropCounters drops;
  private final List<Runnable> connectCallbacks = new CopyOnWriteArrayList<>();
  private final List<Runnable> failedConnectCallbacks = new CopyOnWriteArrayList<>();
  private final List<Runnable> disconnectOnErrorCallbacks = new CopyOnWriteArrayList<>();
  private volatile ArDeviceConnection connection;
  private volatile ArPose sensorPose = ArPose.ORIGIN;
  private volatile boolean flipped;
  private volatile long connectionTimeoutMs = DEFAULT_CONNECTION_TIMEOUT_MS;
  private volatile boolean connected;
  private volatile String failure = "";
  private volatile LaserScan lastScan;

  /** The reader thread while connected. Guarded by {@code this}. */
  private Thread reader;

  /** Scans received since creation. Guarded by {@code this}. */
  private long scanCount;

  /**
   * A laser.
   *
   * @param name the device's name (e.g. "lms2xx_1")
   * @param maxRange farthest reading the device reports, mm
   */
  protected ArLaser(String name, double maxRange) {
    super(name, maxRange, 1024, 2048);
    this.drops = new DropCounters(name);
  }

  /** Sets the connection to read from (not yet open: {@link #blockingConnect} opens it). */
  public void setDeviceConnection(ArDeviceConnection c) {
    connection = c;
  }

  /** The connection, or null. */
  public ArDeviceConnection getDeviceConnection() {
    return connection;
  }

  /** Where the laser sits on the robot (x, y mm forward/left of the centre, th degrees). */
  public void setSensorPosition(double x, double y, double th) {
    sensorPose = new ArPose(x, y, th);
  }

  /** The laser's mounting pose on the robot. */
  public ArPose getSensorPosition() {
    return sensorPose;
  }

  /** Whether the laser is mounted upside down (its angles are then mirrored). */
  public void setFlipped(boolean upsideDown) {
    flipped = upsideDown;
  }

  /** Whether the laser is mounted upside down. */
  public boolean getFlipped() {
    return flipped;
  }

  /** How long the laser may stay silent before it counts as lost, ms. */
  public void setConnectionTimeoutMs(long ms) {
    if (ms <= 0) {
      throw new IllegalArgumentException("the laser connection timeout must be positive: " + ms);
    }
    connectionTimeoutMs = ms;
  }

  /** How long the laser may stay silent before it counts as lost, ms. */
  public long getConnectionTimeoutMs() {
    return connectionTimeoutMs;
  }

  /** Adds a callback run (on the connecting thread) once a connection succeeds. */
  public void addConnectCB(Runnable cb) {
    connectCallbacks.add(cb);
  }

  /** Adds a callback run when a connection attempt fails. */
  public void addFailedConnectCB(Runnable cb) {
    failedConnectCallbacks.add(cb);
  }

  /** Adds a callback run (on the reader thread) when a connected laser is lost. */
  public void addDisconnectOnErrorCB(Runnable cb) {
    disconnectOnErrorCallbacks.add(cb);
  }

  /** Damaged telegrams and skipped bytes. */
  public DropCounters getDropCounters() {
    return drops;
  }

  /** Whether the laser is connected and sending. */
  public boolean isConnected() {
    return connected;
  }

  /** Why the last connection attempt failed or the connection was lost; empty if it did not. */
  public String getConnectFailure() {
    return failure;
  }

  /**
   * Opens the connection (if needed), sets the laser up and starts reading scans. Blocks until the
   * laser answers or the set-up fails.
   *
   * @return whether the laser is now connected; if not, {@link #getConnectFailure()} says why
   */
  public boolean blockingConnect() {
    stopReader();
    ArDeviceConnection c = connection;
    if (c == null) {
      return failed("no connection set for " + getName() + ": give its port with -laserPort");
    }
    try {
      if (c.getStatus() != ArDeviceConnection.Status.OPEN) {
        c.open();
      }
      if (c instanceof ArSerialConnection serial) {
        serial.setBaud(startingBaud(serial));
      }
      handshake(c);
    } catch (IOException e) {
      c.close();
      return failed(getName() + " on " + c.getPortName() + ": " + e.getMessage());
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      c.close();
      return failed(getName() + ": interrupted while connecting");
    }
    failure = "";
    connected = true;
    synchronized (this) {
      Thread t = new Thread(() -> readLoop(c), "laser-" + getName());
      t.setDaemon(true);
      reader = t;
      t.start();
    }
    log.info("{}: connected on {}", getName(), c.getPortName());
    connectCallbacks.forEach(Runnable::run);
    return true;
  }

  private boolean failed(String why) {
    failure = why;
    connected = false;
    log.warn("{}", why);
    failedConnectCallbacks.forEach(Runnable::run);
    return false;
  }

  /**
   * The baud rate to open a serial port at before the set-up (the device's power-up rate); the
   * set-up may switch it.
   */
  protected int startingBaud(ArSerialConnection serial) {
    return serial.getBaud();
  }

  /**
   * Sets the device up on an open connection (baud rate, field of view, units) and starts its
   * measurements. Throws if it does not answer as expected.
   */
  protected abstract void handshake(ArDeviceConnection c) throws IOException, InterruptedException;

  /**
   * Reads what the device sent within about {@code waitMs} and {@link #publish publishes} every
   * complete scan. Throws if the connection fails.
   */
  protected abstract void pump(ArDeviceConnection c, long waitMs) throws IOException;

  /** Stops the device's measurements before a normal disconnect (best effort). */
  protected void stopMeasuring(ArDeviceConnection c) throws IOException {}

  private void readLoop(ArDeviceConnection c) {
    long timeoutNanos = TimeUnit.MILLISECONDS.toNanos(connectionTimeoutMs);
    long lastScanAt = c.clock().nanoTime();
    long seen = getScanCount();
    try {
      while (connected && !Thread.currentThread().isInterrupted()) {
        pump(c, 100);
        long now = c.clock().nanoTime();
        long count = getScanCount();
        if (count != seen) {
          seen = count;
          lastScanAt = now;
        } else if (now - lastScanAt > timeoutNanos) {
          throw new IOException(
              "no scan for "
                  + connectionTimeoutMs
                  + " ms: is the laser unplugged or switched off? check its cable and power, then"
                  + " reconnect");
        }
      }
    } catch (IOException | RuntimeException e) {
      if (connected) {
        connected = false;
        failure = getName() + " on " + c.getPortName() + " lost: " + e.getMessage();
        synchronized (this) {
          notifyAll(); // whoever waits for scans learns it now, not at the end of its timeout
        }
        log.warn("{}", failure);
        c.close();
        disconnectOnErrorCallbacks.forEach(Runnable::run);
      }
    }
  }

  /**
   * Takes one scan: {@code anglesDeg[i]} (relative to the laser, counter-clockwise positive) and
   * {@code rangesMm[i]} (0 or at least the maximum range for "no echo"). Fills the buffers and
   * becomes {@link #getLaserScan()}. Called by the reader thread.
   */
  protected void publish(double[] anglesDeg, double[] rangesMm) {
    double[] angles = anglesDeg.clone();
    if (flipped) {
      for (int i = 0; i < angles.length; i++) {
        angles[i] = -angles[i];
      }
    }
    ArRobot r = getRobot();
    ArPose base = r == null ? ArPose.ORIGIN : r.getPose();
    ArPose mount = sensorPose;
    double c = Math.cos(base.getThRad());
    double s = Math.sin(base.getThRad());
    ArPose sensor =
        new ArPose(
            base.x() + c * mount.x() - s * mount.y(),
            base.y() + s * mount.x() + c * mount.y(),
            base.th() + mount.th());
    LaserScan scan = new LaserScan(sensor, angles, rangesMm, getMaxRange());
    ArDeviceConnection conn = connection;
    long now = conn == null ? System.nanoTime() : conn.clock().nanoTime();
    synchronized (this) {
      currentBuffer.clear();
      for (int i = 0; i < scan.getNumPoints(); i++) {
        currentBuffer.addReading(scan.getX(i), scan.getY(i), now);
        cumulativeBuffer.addReadingConditional(scan.getX(i), scan.getY(i), now, 50);
      }
      lastScan = scan;
      scanCount++;
      notifyAll();
    }
  }

  @Override
  public LaserScan getLaserScan() {
    return lastScan;
  }

  /** Scans received since this laser was created. */
  public synchronized long getScanCount() {
    return scanCount;
  }

  /**
   * Waits until at least {@code n} scans have been received in all, the laser is lost, or {@code
   * timeoutMs} pass (a bound for a program's patience, not a pacing device).
   *
   * @return whether {@code n} scans have arrived
   */
  public synchronized boolean waitForScans(long n, long timeoutMs) throws InterruptedException {
    long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(timeoutMs);
    while (scanCount < n && connected) {
      long left = deadline - System.nanoTime();
      if (left <= 0) {
        return false;
      }
      TimeUnit.NANOSECONDS.timedWait(this, left);
    }
    return scanCount >= n;
  }

  /**
   * Waits until the laser is no longer connected (it was lost or disconnected) or {@code timeoutMs}
   * pass.
   *
   * @return whether it is disconnected
   */
  public boolean waitForDisconnect(long timeoutMs) throws InterruptedException {
    Thread t;
    synchronized (this) {
      t = reader;
    }
    if (t != null) {
      t.join(timeoutMs);
    }
    return !connected;
  }

  /** Stops the measurements and closes the connection; idempotent. */
  public void disconnect() {
    ArDeviceConnection c = connection;
    boolean was = connected;
    stopReader();
    if (c != null) {
      if (was) {
        try {
          stopMeasuring(c);
        } catch (IOException e) {
          log.debug("{}: could not stop the measurements: {}", getName(), e.getMessage());
        }
      }
      c.close();
    }
  }

  private void stopReader() {
    connected = false;
    Thread t;
    synchronized (this) {
      t = reader;
      reader = null;
      notifyAll();
    }
    if (t != null && t != Thread.currentThread()) {
      t.interrupt();
      try {
        t.join(2000);
      } catch (InterruptedException e) {
        Thread.currentThread().interrupt();
      }
    }
  }

  @Override
  public void close() {
    disconnect();
  }
}
