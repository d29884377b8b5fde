package org.jaria.laser;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Queue;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.function.Consumer;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.input.ArKeyHandler;
import org.jaria.laser.log.LogTag;
import org.jaria.laser.log.LoggedScan;
import org.jaria.laser.log.ScanLogEntry;
import org.jaria.laser.log.ScanLogHeader;
import org.jaria.laser.log.ScanLogWriter;
import org.jaria.params.ArRobotParams;
import org.jaria.range.ArRangeDevice;
import org.jaria.range.LaserScan;
import org.jaria.range.LaserScanSource;
import org.jaria.robot.ArRobot;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Writes a laser scan log ({@code .2d}) while the robot drives (ARIA's {@code ArLaserLogger}, the
 * heart of {@code sickLogger}): every time the robot has moved {@code distDiff} mm or turned {@code
 * degDiff} degrees since the last logged scan, the latest sweep is written with the robot's pose,
 * in ARIA's format ({@link ScanLogWriter}), so ARIA's tools and JAria's map builder read it. Goals
 * can be placed on the way ({@link #addGoal()}, the {@code g} key, the robot's joystick button);
 * they become goals of the built map. Readings are written as {@code scan1:} points only (ARIA's
 * optional old {@code sick1:} range lines are not written; the reader reads them in old logs).
 *
 * <p>Three lines in a program whose robot has a laser:
 *
 * <pre>{@code
 * ArLaserLogger logger = new ArLaserLogger(robot, laser, 300, 25, "lab.2d");
 * // ... drive ...
 * logger.close();   // writes "# End of log"
 * }</pre>
 *
 * <p>The log is written by a user task on the robot's cycle (as ARIA does); {@link #addTagToLog},
 * {@link #addGoal()} and {@link #takeReading()} may be called from any thread. ARIA's packet 0x96
 * (loop markers of a MobileRobots mapping firmware feature) is not handled.
 */
public class ArLaserLogger implements AutoCloseable {

  private static final Logger log = LoggerFactory.getLogger(ArLaserLogger.class);

  /** The name of the user task that logs. */
  public static final String TASK_NAME = "Laser Logger";

  /** ARIA's robot flag for the robot's joystick button (used to place goals). */
  private static final int JOYSTICK_BUTTON_FLAG = 1 << 9;

  private final ArRobot robot;
  private final LaserScanSource laser;
  private final String laserName;
  private final ArPose mount;
  private final String fileName;
  private final boolean addGoals;
  private final ArKeyHandler keyHandler;
  private final Queue<String> tags = new ConcurrentLinkedQueue<>();
  private final Queue<String> infos = new ConcurrentLinkedQueue<>();
  private final List<Consumer<ScanLogEntry>> entryCallbacks = new CopyOnWriteArrayList<>();
  private final long startNanos;
  private volatile double distDiff;
  private volatile double degDiff;
  private volatile boolean takeExplicit;
  private volatile boolean goalExplicit;
  private volatile boolean goalKey;

  @GuardedBy("this")
  private ScanLogWriter writer;

  @GuardedBy("this")
  private boolean headerWritten;

  @GuardedBy("this")
  private ScanLogHeader header;

  @GuardedBy("this")
  private boolean firstTaken;

  @GuardedBy("this")
  private ArPose last = ArPose.ORIGIN;

  @GuardedBy("this")
  private double lastVel;

  @GuardedBy("this")
  private int scanNumber;

  @GuardedBy("this")
  private int goalNumber = 1;

  @GuardedBy("this")
  private boolean lastJoyButton;

  @GuardedBy("this")
  private String failure = "";

  /**
   * A logger writing {@code fileName} (in the working directory unless absolute), logging a scan
   * every {@code distDiff} mm or {@code degDiff} degrees ({@code sickLogger} uses 300 and 25).
   *
   * @param laser the robot's laser: {@link ArLaser} or {@link org.jaria.range.ArSimulatedLaser}
   */
  public <L extends ArRangeDevice & LaserScanSource> ArLaserLogger(
      ArRobot robot, L laser, double distDiff, double degDiff, String fileName) {
    this(robot, laser, distDiff, degDiff, fileName, false, null, null);
  }

  /** As above; with {@code addGoals}, the robot's joystick button places a goal. */
  public <L extends ArRangeDevice & LaserScanSource> ArLaserLogger(
      ArRobot robot, L laser, double distDiff, double degDiff, String fileName, boolean addGoals) {
    this(robot, laser, distDiff, degDiff, fileName, addGoals, null, null);
  }

  /**
   * A logger as ARIA's constructor makes it.
   *
   * @param addGoals whether the {@code g} key of {@code keyHandler} and the robot's joystick button
   *     place goals ({@link #addGoal()} always does)
   * @param keyHandler the program's key handler (JAria has no global one), or null
   * @param baseDirectory folder for a relative {@code fileName}, or null for the working directory
   */
  public <L extends ArRangeDevice & LaserScanSource> ArLaserLogger(
      ArRobot robot,
      L laser,
      double distDiff,
      double degDiff,
      String fileName,
      boolean addGoals,
      ArKeyHandler keyHandler,
      Path baseDirectory) {
    this(robot, laser, laser.getName(), distDiff, degDiff, fileName, addGoals, keyHandler);
    Path file =
        baseDirectory == null || Path.of(fileName).isAbsolute()
            ? Path.of(fileName)
            : baseDirectory.resolve(fileName);
    try {
      open(Files.newBufferedWriter(file, StandardCharsets.ISO_8859_1));
    } catch (IOException | RuntimeException e) {
      synchronized (this) {
        failure = "cannot write the scan log " + file + ": " + e.getMessage();
        log.error("ArLaserLogger: {}", failure);
      }
    }
  }

  /**
   * A logger writing to {@code out} instead of a file (a test, or a server streaming the log).
   *
   * @param name the log's name in messages
   */
  public <L extends ArRangeDevice & LaserScanSource> ArLaserLogger(
      ArRobot robot, L laser, double distDiff, double degDiff, Writer out, String name) {
    this(robot, laser, laser.getName(), distDiff, degDiff, name, false, null);
    open(out);
  }

  private ArLaserLogger(
      ArRobot robot,
      LaserScanSource laser,
      String laserName,
      double distDiff,
      double degDiff,
      String fileName,
      boolean addGoals,
      ArKeyHandler keyHandler) {
    this.robot = robot;
    this.laser = laser;
    this.laserName = laserName;
    this.mount = mountOf(robot, laser);
    this.fileName = fileName;
    this.distDiff = Math.abs(distDiff);
    this.degDiff = Math.abs(degDiff);
    this.addGoals = addGoals;
    this.keyHandler = keyHandler;
    this.startNanos = robot.getClock().nanoTime();
  }

  private synchronized void open(Writer out) {
    writer = new ScanLogWriter(out);
    robot.addUserTask(TASK_NAME, 1, this::robotTask);
    if (addGoals && keyHandler != null) {
      Runnable cb = () -> goalKey = true;
      if (!keyHandler.addKeyHandler('g', cb) || !keyHandler.addKeyHandler('G', cb)) {
        log.warn("ArLaserLogger: the key handler already has a key for g; goals by key are off");
      }
    }
  }

  /** Where the laser sits on the robot: the laser's own setting, or the robot's parameters. */
  private static ArPose mountOf(ArRobot robot, LaserScanSource laser) {
    if (laser instanceof ArLaser l) {
      return l.getSensorPosition();
    }
    ArRobotParams p = robot.getRobotParams();
    return new ArPose(p.getLaserX(), p.getLaserY(), p.getLaserTh());
  }

  /** Whether the log file could be opened (ARIA's name). */
  public synchronized boolean wasFileOpenedSuccessfully() {
    return writer != null && failure.isEmpty();
  }

  /** Why the log could not be opened or written; empty if all is well. */
  public synchronized String getFailure() {
    return failure;
  }

  /** The log's file name as given. */
  public String getFileName() {
    return fileName;
  }

  /** Sets the distance the robot must travel before the next scan is logged, mm. */
  public void setDistDiff(double mm) {
    distDiff = Math.abs(mm);
  }

  /** The distance between logged scans, mm. */
  public double getDistDiff() {
    return distDiff;
  }

  /** Sets the angle the robot must turn before the next scan is logged, degrees. */
  public void setDegDiff(double degrees) {
    degDiff = Math.abs(degrees);
  }

  /** The angle between logged scans, degrees. */
  public double getDegDiff() {
    return degDiff;
  }

  /** Logs the next sweep whether or not the robot moved. */
  public void takeReading() {
    takeExplicit = true;
  }

  /** Places a goal where the robot is now ({@code goal1}, {@code goal2}, ... in the map). */
  public void addGoal() {
    goalExplicit = true;
  }

  /**
   * Adds a tag at the robot's current pose and time, e.g. {@code addTagToLog("loop: start %d", 1)}
   * (formatted with {@link String#format}).
   */
  public void addTagToLog(String format, Object... args) {
    addTagToLogPlain(String.format(Locale.ROOT, format, args));
  }

  /** Adds a tag at the robot's current pose and time, unformatted. */
  public void addTagToLogPlain(String text) {
    tags.add(oneLine(text));
  }

  /** Adds a line of its own (no time or pose), formatted with {@link String#format}. */
  public void addInfoToLog(String format, Object... args) {
    addInfoToLogPlain(String.format(Locale.ROOT, format, args));
  }

  /** Adds a line of its own, unformatted. */
  public void addInfoToLogPlain(String text) {
    infos.add(oneLine(text));
  }

  private static String oneLine(String s) {
    return s.replace('\n', ' ').replace('\r', ' ');
  }

  /**
   * Calls {@code cb} with every scan and tag right after it is written, on the robot's cycle thread
   * (keep it short: hand the entry to another thread, e.g. a map builder's queue).
   */
  public void addEntryCB(Consumer<ScanLogEntry> cb) {
    entryCallbacks.add(cb);
  }

  /** Removes a callback added with {@link #addEntryCB}. */
  public void remEntryCB(Consumer<ScanLogEntry> cb) {
    entryCallbacks.remove(cb);
  }

  /**
   * The log's header (the laser's mounting and view) once written, else null: a builder that gets
   * the entries from {@link #addEntryCB} needs it (it is written before the first entry).
   */
  public synchronized ScanLogHeader getHeader() {
    return header;
  }

  /** Scans logged so far. */
  public synchronized int getScanCount() {
    return scanNumber;
  }

  /** The task: goals, then tags, then a scan if the robot moved enough (ARIA's order). */
  private synchronized void robotTask() {
    if (writer == null || !failure.isEmpty()) {
      return;
    }
    try {
      internalAddGoal();
      internalWriteTags();
      internalTakeReading();
    } catch (IOException e) {
      failure = "writing the scan log " + fileName + " failed: " + e.getMessage();
      log.error("ArLaserLogger: {}", failure);
    }
  }

  @GuardedBy("this")
  private void internalAddGoal() {
    boolean joy = addGoals && (robot.getFlags() & JOYSTICK_BUTTON_FLAG) != 0;
    boolean key = goalKey;
    goalKey = false;
    if (robot.isConnected() && (goalExplicit || (addGoals && key) || (joy && !lastJoyButton))) {
      goalExplicit = false;
      tags.add("cairn: GoalWithHeading \"\" ICON_GOALWITHHEADING \"goal" + goalNumber + "\"");
      log.info("Goal {} taken", goalNumber);
      goalNumber++;
    }
    lastJoyButton = joy;
  }

  @GuardedBy("this")
  private void internalWriteTags() throws IOException {
    if (!headerWritten && (!tags.isEmpty() || !infos.isEmpty())) {
      LaserScan s = laser.getLaserScan();
      if (s == null) {
        return; // the header needs the laser's field of view: wait for its first sweep
      }
      writeHeader(s);
    }
    for (String info = infos.poll(); info != null; info = infos.poll()) {
      writer.writeInfo(info);
    }
    for (String text = tags.poll(); text != null; text = tags.poll()) {
      LogTag t = new LogTag(elapsed(), robot.getEncoderPose(), robot.getPose(), text);
      writer.writeTag(t);
      entryCallbacks.forEach(cb -> cb.accept(t));
    }
  }

  @GuardedBy("this")
  private void internalTakeReading() throws IOException {
    LaserScan scan = laser.getLaserScan();
    if (scan == null || !robot.isConnected()) {
      return;
    }
    ArPose enc = robot.getEncoderPose();
    double vel = robot.getVel();
    double moved = last.findDistanceTo(enc);
    boolean reversed = (lastVel < 0 && vel > 0) || (lastVel > 0 && vel < 0);
    if (firstTaken
        && !takeExplicit
        && moved <= distDiff
        && Math.abs(ArMath.subAngle(last.th(), enc.th())) <= degDiff
        && !(reversed && moved > 50)) {
      return;
    }
    takeExplicit = false;
    firstTaken = true;
    last = enc;
    lastVel = vel;
    if (!headerWritten) {
      writeHeader(scan);
    }
    LoggedScan logged = toLogged(scan, enc, vel);
    writer.writeScan(logged);
    scanNumber++;
    entryCallbacks.forEach(cb -> cb.accept(logged));
  }

  @GuardedBy("this")
  private void writeHeader(LaserScan s) throws IOException {
    headerWritten = true;
    int n = s.size();
    double first = n == 0 ? 0 : s.getAngle(0);
    double lastAngle = n == 0 ? 0 : s.getAngle(n - 1);
    header = ScanLogHeader.of(mount, first, lastAngle, n, laserName);
    writer.writeHeader(header);
  }

  /**
   * The scan as logged: the robot's poses when it was taken and its readings in the laser's frame.
   * The scan carries the laser's global pose then; the robot's pose follows from the mounting, and
   * its odometry pose from the current offset between odometry and global pose.
   */
  @GuardedBy("this")
  private LoggedScan toLogged(LaserScan scan, ArPose encNow, double vel) {
    ArPose globalTaken = compose(scan.getSensorPose(), inverse(mount));
    ArPose encTaken = compose(compose(encNow, inverse(robot.getPose())), globalTaken);
    int n = scan.size();
    double[] xs = new double[n];
    double[] ys = new double[n];
    double max = scan.getMaxRange();
    for (int i = 0; i < n; i++) {
      double r = scan.getRange(i);
      if (r > 0 && r < max) {
        double a = Math.toRadians(scan.getAngle(i));
        xs[i] = r * Math.cos(a);
        ys[i] = r * Math.sin(a);
      }
    }
    return new LoggedScan(
        scanNumber, elapsed(), vel, robot.getRotVel(), 0, encTaken, globalTaken, xs, ys);
  }

  private double elapsed() {
    return (robot.getClock().nanoTime() - startNanos) / 1e9;
  }

  static ArPose compose(ArPose a, ArPose b) {
    double c = Math.cos(a.getThRad());
    double s = Math.sin(a.getThRad());
    return new ArPose(
        a.x() + c * b.x() - s * b.y(), a.y() + s * b.x() + c * b.y(), a.th() + b.th());
  }

  static ArPose inverse(ArPose a) {
    double c = Math.cos(a.getThRad());
    double s = Math.sin(a.getThRad());
    return new ArPose(-c * a.x() - s * a.y(), s * a.x() - c * a.y(), -a.th());
  }

  /**
   * Stops logging and closes the log ({@code # End of log}). Safe to call more than once and from
   * any thread.
   */
  @Override
  public void close() {
    robot.remUserTask(TASK_NAME);
    synchronized (this) {
      if (writer == null) {
        return;
      }
      try {
        if (!headerWritten) {
          LaserScan s = laser.getLaserScan();
          if (s != null) {
            writeHeader(s);
          }
        }
        writer.close();
      } catch (IOException e) {
        if (failure.isEmpty()) {
          failure = "closing the scan log " + fileName + " failed: " + e.getMessage();
          log.error("ArLaserLogger: {}", failure);
        }
      }
      writer = null;
    }
  }
}
