package org.jaria.params;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.SortedMap;
import java.util.TreeMap;

/**
 * What ARIA knows about a robot model: size, speed limits, conversion factors between robot units
 * and mm/degrees, sensors and accessories. ARIA's {@code ArRobotParams}, immutable.
 *
 * <p>Built in layers, as ARIA does after connecting (thesis 5.1.41): {@link #defaults()} (a generic
 * Pioneer), then the file for the robot's subtype (for example {@code p3dx-sh.p}, shipped with
 * JAria or supplied by the user), then a file named after the robot itself, which "has the last
 * word". Each layer replaces the keywords it mentions; {@code SonarUnit} and {@code IRUnit} lines
 * replace the unit with the same number and leave the others. Within one file, a keyword that
 * appears more than once counts at its first appearance (in ARIA's files the later appearances
 * belong to a second laser, PTZ or camera).
 *
 * <p>Getters are ARIA's, with ARIA's types. A value of 0 in {@code RobotLengthFront} or {@code
 * RobotLengthRear} means half of {@code RobotLength}. Keywords without a getter are available as
 * text through {@link #getRaw(String)}.
 */
public final class ArRobotParams {

  /** Classpath folder of the parameter files shipped with JAria. */
  public static final String RESOURCE_DIR = "/org/jaria/params/";

  /** The subtypes JAria ships a parameter file for. */
  public static final List<String> BUNDLED_SUBTYPES =
      List.of(
          "amigo",
          "amigo-sh",
          "p2at",
          "p2dx",
          "p3at",
          "p3at-sh",
          "p3dx",
          "p3dx-sh",
          "p3dx-sh-lms",
          "peoplebot-sh");

  private static final ArRobotParams DEFAULTS = ParamLayers.generic();

  // The layers' text, kept for the next layer (ParamLayers) and for getRaw; all unmodifiable.
  final Map<String, ParamFile.Entry> raw;
  final SortedMap<Integer, SonarUnit> sonarUnits;
  final SortedMap<Integer, IRUnit> irUnits;
  final List<String> sources;
  final List<String> problems;

  private final String className;
  private final String subClassName;
  private final double robotRadius;
  private final double robotDiagonal;
  private final double robotWidth;
  private final double robotLength;
  private final double robotLengthFront;
  private final double robotLengthRear;
  private final boolean holonomic;
  private final int maxRVelocity;
  private final int maxVelocity;
  private final int maxLatVelocity;
  private final boolean hasMoveCommand;
  private final boolean requestIOPackets;
  private final boolean requestEncoderPackets;
  private final int switchToBaudRate;
  private final double angleConvFactor;
  private final double distConvFactor;
  private final double velConvFactor;
  private final double rangeConvFactor;
  private final double diffConvFactor;
  private final double vel2Divisor;
  private final double gyroScaler;
  private final boolean tableSensingIR;
  private final boolean newTableSensingIR;
  private final boolean frontBumpers;
  private final int numFrontBumpers;
  private final boolean rearBumpers;
  private final int numRearBumpers;
  private final boolean settableVelMaxes;
  private final int transVelMax;
  private final int rotVelMax;
  private final boolean settableAccsDecs;
  private final int transAccel;
  private final int transDecel;
  private final int rotAccel;
  private final int rotDecel;
  private final boolean hasLatVel;
  private final int latVelMax;
  private final int latAccel;
  private final int latDecel;
  private final int laserX;
  private final int laserY;
  private final double laserTh;
  private final int laserMaxRange;
  private final String compassType;
  private final int numSonar;
  private final SonarUnit[] sonars;
  private final int numIR;
  private final IRUnit[] irs;

  ArRobotParams(
      Map<String, ParamFile.Entry> raw,
      SortedMap<Integer, SonarUnit> sonarUnits,
      SortedMap<Integer, IRUnit> irUnits,
      List<String> sources,
      List<String> problems)
      throws ParamFormatException {
    this.raw = Collections.unmodifiableMap(new LinkedHashMap<>(raw));
    this.sonarUnits = Collections.unmodifiableSortedMap(new TreeMap<>(sonarUnits));
    this.irUnits = Collections.unmodifiableSortedMap(new TreeMap<>(irUnits));
    this.sources = List.copyOf(sources);
    this.problems = List.copyOf(problems);
    ParamValues v = new ParamValues(this.raw);
    className = v.string("Class");
    subClassName = v.string("Subclass");
    robotRadius = v.number("RobotRadius");
    robotDiagonal = v.number("RobotDiagonal");
    robotWidth = v.number("RobotWidth");
    robotLength = v.number("RobotLength");
    double front = v.number("RobotLengthFront");
    double rear = v.number("RobotLengthRear");
    robotLengthFront = front == 0 ? robotLength / 2 : front;
    robotLengthRear = rear == 0 ? robotLength / 2 : rear;
    holonomic = v.bool("Holonomic");
    maxRVelocity = v.integer("MaxRVelocity");
    maxVelocity = v.integer("MaxVelocity");
    maxLatVelocity = v.integer("MaxLatVelocity");
    hasMoveCommand = v.bool("HasMoveCommand");
    requestIOPackets = v.bool("RequestIOPackets");
    requestEncoderPackets = v.bool("RequestEncoderPackets");
    switchToBaudRate = v.integer("SwitchToBaudRate");
    angleConvFactor = v.number("AngleConvFactor");
    distConvFactor = v.number("DistConvFactor");
    velConvFactor = v.number("VelConvFactor");
    rangeConvFactor = v.number("RangeConvFactor");
    diffConvFactor = v.number("DiffConvFactor");
    vel2Divisor = v.number("Vel2Divisor");
    gyroScaler = v.number("GyroScaler");
    tableSensingIR = v.bool("TableSensingIR");
    newTableSensingIR = v.bool("NewTableSensingIR");
    frontBumpers = v.bool("FrontBumpers");
    numFrontBumpers = v.count("NumFrontBumpers");
    rearBumpers = v.bool("RearBumpers");
    numRearBumpers = v.count("NumRearBumpers");
    settableVelMaxes = v.bool("SettableVelMaxes");
    transVelMax = v.integer("TransVelMax");
    rotVelMax = v.integer("RotVelMax");
    settableAccsDecs = v.bool("SettableAccsDecs");
    transAccel = v.integer("TransAccel");
    transDecel = v.integer("TransDecel");
    rotAccel = v.integer("RotAccel");
    rotDecel = v.integer("RotDecel");
    hasLatVel = v.bool("HasLatVel");
    latVelMax = v.integer("LatVelMax");
    latAccel = v.integer("LatAccel");
    latDecel = v.integer("LatDecel");
    laserX = v.integer("LaserX");
    laserY = v.integer("LaserY");
    laserTh = v.number("LaserTh");
    laserMaxRange = v.integer("LaserMaxRange");
    compassType = v.string("CompassType");
    numSonar = v.count("SonarNum");
    sonars = new SonarUnit[numSonar];
    for (int i = 0; i < numSonar; i++) {
      sonars[i] = this.sonarUnits.getOrDefault(i, new SonarUnit(i, 0, 0, 0));
    }
    numIR = v.count("IRNum");
    irs = new IRUnit[numIR];
    for (int i = 0; i < numIR; i++) {
      irs[i] = this.irUnits.getOrDefault(i, new IRUnit(i, 0, 0, 0, 0));
    }
    ParamChecks.plausible(this);
  }

  /** The generic Pioneer values every robot starts from (no sonars: their places vary). */
  public static ArRobotParams defaults() {
    return DEFAULTS;
  }

  /**
   * Generic defaults with the parameter file shipped for {@code subtype} on top (looked up
   * lower-cased, e.g. "p3dx-sh"). An unknown subtype is not an error: a WARN is logged and the
   * generic defaults are returned.
   */
  public static ArRobotParams forSubtype(String subtype) {
    return ParamsLoader.forSubtype(subtype);
  }

  /** The parameter file JAria ships for this subtype, if any. */
  public static Optional<ParamFile> bundledFile(String subtype) {
    return ParamsLoader.bundledFile(subtype);
  }

  /**
   * The parameters of a connected robot, as ARIA loads them: generic defaults, then {@code
   * <subtype>.p} (from {@code userDir} if there is one there, else the bundled one), then {@code
   * userDir/<robotName>.p} if present. A user file that cannot be read or parsed is skipped with an
   * ERROR in the log naming file and line; use {@link #loadStrict} to get the exception instead.
   *
   * @param subtype the subtype the robot reported (e.g. "p3dx-sh")
   * @param robotName the robot's name from its FLASH, may be null
   * @param userDir folder with the user's parameter files, may be null
   */
  public static ArRobotParams load(String subtype, String robotName, Path userDir) {
    return ParamsLoader.load(subtype, robotName, userDir);
  }

  /**
   * Like {@link #load} but a user file that cannot be read or parsed is an error.
   *
   * @throws ParamFormatException if a user file is malformed
   * @throws IOException if a user file exists but cannot be read
   */
  public static ArRobotParams loadStrict(String subtype, String robotName, Path userDir)
      throws ParamFormatException, IOException {
    return ParamsLoader.loadStrict(subtype, robotName, userDir);
  }

  /**
   * A new parameter set with {@code f}'s values on top of this one's.
   *
   * @throws ParamFormatException if a value in {@code f} has the wrong form for its keyword (a
   *     number that is not one, a SonarUnit with missing fields...); the message names file and
   *     line
   */
  public ArRobotParams overlay(ParamFile f) throws ParamFormatException {
    return ParamLayers.layer(this, f);
  }

  /**
   * This set with a note on a file that could not be used (see {@link #getProblems()}).
   *
   * @throws IllegalStateException never in practice: the values were accepted before
   */
  ArRobotParams withProblem(String problem) {
    List<String> all = new ArrayList<>(problems);
    all.add(problem);
    try {
      return new ArRobotParams(raw, sonarUnits, irUnits, sources, all);
    } catch (ParamFormatException e) {
      throw new IllegalStateException("values accepted once were refused: " + e.getMessage(), e);
    }
  }

  /**
   * What went wrong loading this set: one "file:line: what" message per user file that could not be
   * used (and was replaced by the bundled file for the subtype). Empty when every file was used. A
   * connect callback can show these; {@link #getSources()} says which files were used.
   */
  public List<String> getProblems() {
    return problems;
  }

  /** The text value of any keyword (case-insensitive) from the topmost layer that has it. */
  public Optional<String> getRaw(String keyword) {
    ParamFile.Entry e = raw.get(keyword.toLowerCase(Locale.ROOT));
    return e == null ? Optional.empty() : Optional.of(e.value());
  }

  /** The entry behind {@link #getRaw}, with the file and line it came from. */
  public Optional<ParamFile.Entry> getRawEntry(String keyword) {
    return Optional.ofNullable(raw.get(keyword.toLowerCase(Locale.ROOT)));
  }

  /** The layers this set was built from, bottom first (the built-in defaults, then files). */
  public List<String> getSources() {
    return sources;
  }

  /** General type of robot, e.g. "Pioneer". */
  public String getClassName() {
    return className;
  }

  /** Specific type of robot, e.g. "p3dx-sh" ("" for the generic defaults). */
  public String getSubClassName() {
    return subClassName;
  }

  /** Radius of the circle the robot turns in, mm. */
  public double getRobotRadius() {
    return robotRadius;
  }

  /** Half-height to the diagonal of the octagonal body, mm (old Pioneers). */
  public double getRobotDiagonal() {
    return robotDiagonal;
  }

  /** Width, mm. */
  public double getRobotWidth() {
    return robotWidth;
  }

  /** Length, mm. */
  public double getRobotLength() {
    return robotLength;
  }

  /** Distance from the centre of rotation to the front, mm (half the length if the file says 0). */
  public double getRobotLengthFront() {
    return robotLengthFront;
  }

  /** Distance from the centre of rotation to the rear, mm (half the length if the file says 0). */
  public double getRobotLengthRear() {
    return robotLengthRear;
  }

  /** Whether the robot can turn in place. */
  public boolean isHolonomic() {
    return holonomic;
  }

  /** Absolute maximum rotational speed, deg/s ({@code MaxRVelocity}). */
  public int getAbsoluteMaxRotVelocity() {
    return maxRVelocity;
  }

  /** Absolute maximum translational speed, mm/s ({@code MaxVelocity}). */
  public int getAbsoluteMaxVelocity() {
    return maxVelocity;
  }

  /** Absolute maximum lateral speed, mm/s (0 for robots that cannot move sideways). */
  public int getAbsoluteMaxLatVelocity() {
    return maxLatVelocity;
  }

  /** Whether the firmware has the MOVE command. */
  public boolean hasMoveCommand() {
    return hasMoveCommand;
  }

  /** Whether IO packets should be requested automatically after connecting. */
  public boolean getRequestIOPackets() {
    return requestIOPackets;
  }

  /** Whether encoder packets should be requested automatically after connecting. */
  public boolean getRequestEncoderPackets() {
    return requestEncoderPackets;
  }

  /** Serial baud rate to switch to after connecting, 0 to stay at the connection rate. */
  public int getSwitchToBaudRate() {
    return switchToBaudRate;
  }

  /** Radians per robot angle unit (2π/4096 ≈ 0.001534). */
  public double getAngleConvFactor() {
    return angleConvFactor;
  }

  /** mm per robot distance unit (1.0 on SH robots, about 0.485 on old P3-DX H8 controllers). */
  public double getDistConvFactor() {
    return distConvFactor;
  }

  /** mm/s per robot velocity unit. */
  public double getVelConvFactor() {
    return velConvFactor;
  }

  /** mm per sonar range unit. */
  public double getRangeConvFactor() {
    return rangeConvFactor;
  }

  /** Ratio of angular velocity to wheel velocity difference (older firmware). */
  public double getDiffConvFactor() {
    return diffConvFactor;
  }

  /** Divisor of the wheel speeds in VEL2 commands. */
  public double getVel2Divisor() {
    return vel2Divisor;
  }

  /** Scale of the gyro's rate readings. */
  public double getGyroScaler() {
    return gyroScaler;
  }

  /** Whether the robot has upward-facing table-sensing IRs. */
  public boolean haveTableSensingIR() {
    return tableSensingIR;
  }

  /** Whether table-sensing IR states come in the IO packet (newer robots). */
  public boolean haveNewTableSensingIR() {
    return newTableSensingIR;
  }

  /** Whether a front bump ring is fitted. */
  public boolean haveFrontBumpers() {
    return frontBumpers;
  }

  /** Number of front bumper segments. */
  public int getNumFrontBumpers() {
    return numFrontBumpers;
  }

  /** Whether a rear bump ring is fitted. */
  public boolean haveRearBumpers() {
    return rearBumpers;
  }

  /** Number of rear bumper segments. */
  public int getNumRearBumpers() {
    return numRearBumpers;
  }

  /** Number of IR sensors ({@code IRNum}). */
  public int getNumIR() {
    return numIR;
  }

  private IRUnit ir(int i) {
    if (i < 0 || i >= numIR) {
      throw new IndexOutOfBoundsException("IR " + i + " asked for; this robot has " + numIR);
    }
    return irs[i];
  }

  /** X position of IR {@code i}, mm. */
  public int getIRX(int i) {
    return ir(i).x();
  }

  /** Y position of IR {@code i}, mm. */
  public int getIRY(int i) {
    return ir(i).y();
  }

  /** Type of IR {@code i}. */
  public int getIRType(int i) {
    return ir(i).type();
  }

  /** Persistence of IR {@code i}, robot cycles. */
  public int getIRCycles(int i) {
    return ir(i).cycles();
  }

  /** Every IR unit defined, by number (may include numbers beyond {@link #getNumIR()}). */
  public List<IRUnit> getIRUnits() {
    return List.copyOf(irUnits.values());
  }

  /** Number of sonars ({@code SonarNum}). */
  public int getNumSonar() {
    return numSonar;
  }

  private SonarUnit sonar(int i) {
    if (i < 0 || i >= numSonar) {
      throw new IndexOutOfBoundsException(
          "sonar " + i + " asked for; this robot has " + numSonar + " (0.." + (numSonar - 1) + ")");
    }
    return sonars[i];
  }

  /** X position of sonar {@code i}, mm forward of the centre of rotation. */
  public int getSonarX(int i) {
    return sonar(i).x();
  }

  /** Y position of sonar {@code i}, mm left of the centre of rotation. */
  public int getSonarY(int i) {
    return sonar(i).y();
  }

  /** Heading of sonar {@code i}, degrees counter-clockwise from straight ahead. */
  public int getSonarTh(int i) {
    return sonar(i).th();
  }

  /** Sonar {@code i} with all its fields. */
  public SonarUnit getSonarUnit(int i) {
    return sonar(i);
  }

  /** Every sonar unit defined, by number (may include numbers beyond {@link #getNumSonar()}). */
  public List<SonarUnit> getSonarUnits() {
    return List.copyOf(sonarUnits.values());
  }

  /** Whether TransVelMax and RotVelMax may be sent to the robot. */
  public boolean hasSettableVelMaxes() {
    return settableVelMaxes;
  }

  /** Desired maximum translational speed, mm/s; 0 keeps the robot's own value. */
  public int getTransVelMax() {
    return transVelMax;
  }

  /** Desired maximum rotational speed, deg/s; 0 keeps the robot's own value. */
  public int getRotVelMax() {
    return rotVelMax;
  }

  /** Whether accelerations and decelerations may be sent to the robot. */
  public boolean hasSettableAccsDecs() {
    return settableAccsDecs;
  }

  /** Translational acceleration, mm/s²; 0 keeps the robot's own value. */
  public int getTransAccel() {
    return transAccel;
  }

  /** Translational deceleration, mm/s²; 0 keeps the robot's own value. */
  public int getTransDecel() {
    return transDecel;
  }

  /** Rotational acceleration, deg/s²; 0 keeps the robot's own value. */
  public int getRotAccel() {
    return rotAccel;
  }

  /** Rotational deceleration, deg/s²; 0 keeps the robot's own value. */
  public int getRotDecel() {
    return rotDecel;
  }

  /** Whether the robot can move sideways. */
  public boolean hasLatVel() {
    return hasLatVel;
  }

  /** Desired maximum lateral speed, mm/s; 0 keeps the robot's own value. */
  public int getLatVelMax() {
    return latVelMax;
  }

  /** Lateral acceleration, mm/s². */
  public int getLatAccel() {
    return latAccel;
  }

  /** Lateral deceleration, mm/s². */
  public int getLatDecel() {
    return latDecel;
  }

  /** X position of the (first) laser, mm forward of the centre of rotation. */
  public int getLaserX() {
    return laserX;
  }

  /** Y position of the (first) laser, mm left of the centre of rotation. */
  public int getLaserY() {
    return laserY;
  }

  /** Rotation of the (first) laser, degrees counter-clockwise. */
  public double getLaserTh() {
    return laserTh;
  }

  /** Maximum laser range to use, mm; 0 means the laser's own default. */
  public int getLaserMaxRange() {
    return laserMaxRange;
  }

  /** Compass type: "robot" (in the SIP) or "serialTCM" (on a computer serial port). */
  public String getCompassType() {
    return compassType;
  }

  @Override
  public String toString() {
    return "ArRobotParams[" + className + " " + subClassName + " from " + sources + "]";
  }
}
