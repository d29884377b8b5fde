package org.jaria.sim.robot;

import java.util.Arrays;

/**
 * The physical description of one kind of simulated robot: its footprint, sonar ring, speed limits,
 * conversion factors and laser mount. Built from ARIA robot parameters by {@link
 * org.jaria.sim.RobotModels}. Immutable.
 */
public final class RobotModel {

  private final String robotClass;
  private final String subtype;
  private final double lengthFront;
  private final double lengthRear;
  private final double width;
  private final double radius;
  private final double transVelTop;
  private final double rotVelTop;
  private final double transAccTop;
  private final double rotAccTop;
  private final double transVelMax;
  private final double rotVelMax;
  private final double transAccel;
  private final double transDecel;
  private final double rotAccel;
  private final double rotDecel;
  private final double distConv;
  private final double angleConv;
  private final double velConv;
  private final double rangeConv;
  private final double diffConv;
  private final double vel2Divisor;
  private final double gyroScaler;
  private final double[] sonarX;
  private final double[] sonarY;
  private final double[] sonarTh;
  private final int frontBumpers;
  private final int rearBumpers;
  private final double laserX;
  private final double laserY;
  private final double laserTh;
  private final double laserMaxRange;

  private RobotModel(Builder b) {
    robotClass = b.robotClass;
    subtype = b.subtype;
    lengthFront = b.lengthFront;
    lengthRear = b.lengthRear;
    width = b.width;
    radius =
        b.radius > 0 ? b.radius : Math.hypot(Math.max(b.lengthFront, b.lengthRear), b.width / 2);
    transVelTop = b.transVelTop;
    rotVelTop = b.rotVelTop;
    transAccTop = b.transAccTop;
    rotAccTop = b.rotAccTop;
    transVelMax = Math.min(b.transVelMax, b.transVelTop);
    rotVelMax = Math.min(b.rotVelMax, b.rotVelTop);
    transAccel = Math.min(b.transAccel, b.transAccTop);
    transDecel = Math.min(b.transDecel, b.transAccTop);
    rotAccel = Math.min(b.rotAccel, b.rotAccTop);
    rotDecel = Math.min(b.rotDecel, b.rotAccTop);
    distConv = b.distConv;
    angleConv = b.angleConv;
    velConv = b.velConv;
    rangeConv = b.rangeConv;
    diffConv = b.diffConv;
    vel2Divisor = b.vel2Divisor;
    gyroScaler = b.gyroScaler;
    sonarX = Arrays.copyOf(b.sonarX, b.numSonar);
    sonarY = Arrays.copyOf(b.sonarY, b.numSonar);
    sonarTh = Arrays.copyOf(b.sonarTh, b.numSonar);
    frontBumpers = b.frontBumpers;
    rearBumpers = b.rearBumpers;
    laserX = b.laserX;
    laserY = b.laserY;
    laserTh = b.laserTh;
    laserMaxRange = b.laserMaxRange;
  }

  /** A builder with generic Pioneer values. */
  public static Builder builder(String subtype) {
    return new Builder(subtype);
  }

  /** Robot type reported in the handshake, e.g. "Pioneer". */
  public String getRobotClass() {
    return robotClass;
  }

  /** Robot subtype reported in the handshake, e.g. "p3dx-sh". */
  public String getSubtype() {
    return subtype;
  }

  /** Distance from the centre of rotation to the front, mm. */
  public double getLengthFront() {
    return lengthFront;
  }

  /** Distance from the centre of rotation to the back, mm. */
  public double getLengthRear() {
    return lengthRear;
  }

  /** Width, mm. */
  public double getWidth() {
    return width;
  }

  /** Radius of the robot, mm (ARIA's RobotRadius). */
  public double getRadius() {
    return radius;
  }

  /** Highest translational speed the firmware allows (MaxVelocity), mm/s. */
  public double getTransVelTop() {
    return transVelTop;
  }

  /** Highest rotational speed the firmware allows (MaxRVelocity), deg/s. */
  public double getRotVelTop() {
    return rotVelTop;
  }

  /** Highest translational (de)acceleration, mm/s²; used by E_STOP. */
  public double getTransAccTop() {
    return transAccTop;
  }

  /** Highest rotational (de)acceleration, deg/s²; used by E_STOP. */
  public double getRotAccTop() {
    return rotAccTop;
  }

  /** Default maximum translational speed of a session (SETV), mm/s. */
  public double getTransVelMax() {
    return transVelMax;
  }

  /** Default maximum rotational speed of a session (SETRV), deg/s. */
  public double getRotVelMax() {
    return rotVelMax;
  }

  /** Default translational acceleration, mm/s². */
  public double getTransAccel() {
    return transAccel;
  }

  /** Default translational deceleration, mm/s². */
  public double getTransDecel() {
    return transDecel;
  }

  /** Default rotational acceleration, deg/s². */
  public double getRotAccel() {
    return rotAccel;
  }

  /** Default rotational deceleration, deg/s². */
  public double getRotDecel() {
    return rotDecel;
  }

  /** Millimetres per SIP distance unit. */
  public double getDistConvFactor() {
    return distConv;
  }

  /** Radians per SIP angle unit. */
  public double getAngleConvFactor() {
    return angleConv;
  }

  /** Millimetres per second per SIP velocity unit. */
  public double getVelConvFactor() {
    return velConv;
  }

  /** Millimetres per SIP sonar range unit. */
  public double getRangeConvFactor() {
    return rangeConv;
  }

  /** ARIA's DiffConvFactor: rotational velocity (rad/s) per wheel velocity difference / 2. */
  public double getDiffConvFactor() {
    return diffConv;
  }

  /** Distance between the wheels implied by DiffConvFactor, mm. */
  public double getTrackWidth() {
    return diffConv > 0 ? 2 / diffConv : width;
  }

  /** mm/s per VEL2 unit. */
  public double getVel2Divisor() {
    return vel2Divisor;
  }

  /** ARIA's GyroScaler: degrees per second per gyro count ÷ 0.5865. */
  public double getGyroScaler() {
    return gyroScaler;
  }

  /** Number of sonar transducers. */
  public int getNumSonar() {
    return sonarX.length;
  }

  /** X of sonar {@code i} on the robot, mm (+ forward). */
  public double getSonarX(int i) {
    return sonarX[i];
  }

  /** Y of sonar {@code i} on the robot, mm (+ left). */
  public double getSonarY(int i) {
    return sonarY[i];
  }

  /** Heading of sonar {@code i} on the robot, degrees (+ counter-clockwise). */
  public double getSonarTh(int i) {
    return sonarTh[i];
  }

  /** Number of front bumper segments. */
  public int getNumFrontBumpers() {
    return frontBumpers;
  }

  /** Number of rear bumper segments. */
  public int getNumRearBumpers() {
    return rearBumpers;
  }

  /** Laser mount x, mm. */
  public double getLaserX() {
    return laserX;
  }

  /** Laser mount y, mm. */
  public double getLaserY() {
    return laserY;
  }

  /** Laser mount heading, degrees. */
  public double getLaserTh() {
    return laserTh;
  }

  /** Laser maximum range, mm. */
  public double getLaserMaxRange() {
    return laserMaxRange;
  }

  @Override
  public String toString() {
    return "RobotModel[" + subtype + ", " + getNumSonar() + " sonar]";
  }

  /** Collects the values of a {@link RobotModel}; starts with generic Pioneer values. */
  public static final class Builder {
    private String robotClass = "Pioneer";
    private final String subtype;
    private double lengthFront = 255;
    private double lengthRear = 255;
    private double width = 400;
    private double radius;
    private double transVelTop = 2200;
    private double rotVelTop = 500;
    private double transAccTop = 2000;
    private double rotAccTop = 500;
    private double transVelMax = 1500;
    private double rotVelMax = 300;
    private double transAccel = 300;
    private double transDecel = 300;
    private double rotAccel = 100;
    private double rotDecel = 100;
    private double distConv = 1;
    private double angleConv = 0.001534;
    private double velConv = 1;
    private double rangeConv = 1;
    private double diffConv = 0.0056;
    private double vel2Divisor = 20;
    private double gyroScaler = 1.626;
    private double[] sonarX = new double[0];
    private double[] sonarY = new double[0];
    private double[] sonarTh = new double[0];
    private int numSonar;
    private int frontBumpers = 5;
    private int rearBumpers = 5;
    private double laserX = 160;
    private double laserY;
    private double laserTh;
    private double laserMaxRange = 32000;

    private Builder(String subtype) {
      this.subtype = subtype;
    }

    /** Robot type. */
    public Builder robotClass(String c) {
      robotClass = c;
      return this;
    }

    /** Footprint: front and rear length from the centre of rotation, width, mm. */
    public Builder footprint(double front, double rear, double w) {
      lengthFront = front;
      lengthRear = rear;
      width = w;
      return this;
    }

    /** Robot radius, mm (0 = computed from the footprint). */
    public Builder radius(double r) {
      radius = r;
      return this;
    }

    /** Firmware top speeds, mm/s and deg/s. */
    public Builder velTops(double trans, double rot) {
      transVelTop = trans;
      rotVelTop = rot;
      return this;
    }

    /** Firmware top accelerations, mm/s² and deg/s². */
    public Builder accTops(double trans, double rot) {
      transAccTop = trans;
      rotAccTop = rot;
      return this;
    }

    /** Default session maximum speeds, mm/s and deg/s. */
    public Builder velMaxes(double trans, double rot) {
      transVelMax = trans;
      rotVelMax = rot;
      return this;
    }

    /** Default session accelerations and decelerations. */
    public Builder accels(double tAcc, double tDec, double rAcc, double rDec) {
      transAccel = tAcc;
      transDecel = tDec;
      rotAccel = rAcc;
      rotDecel = rDec;
      return this;
    }

    /** Conversion factors (ARIA's parameter names). */
    public Builder conversions(
        double dist, double angle, double vel, double range, double diff, double vel2Div) {
      distConv = dist;
      angleConv = angle;
      velConv = vel;
      rangeConv = range;
      diffConv = diff;
      vel2Divisor = vel2Div;
      return this;
    }

    /** ARIA's GyroScaler. */
    public Builder gyroScaler(double s) {
      gyroScaler = s;
      return this;
    }

    /** Adds the next sonar transducer (mm, mm, degrees). */
    public Builder addSonar(double x, double y, double th) {
      if (numSonar == sonarX.length) {
        int cap = Math.max(8, numSonar * 2);
        sonarX = Arrays.copyOf(sonarX, cap);
        sonarY = Arrays.copyOf(sonarY, cap);
        sonarTh = Arrays.copyOf(sonarTh, cap);
      }
      sonarX[numSonar] = x;
      sonarY[numSonar] = y;
      sonarTh[numSonar] = th;
      numSonar++;
      return this;
    }

    /** Numbers of bumper segments. */
    public Builder bumpers(int front, int rear) {
      frontBumpers = front;
      rearBumpers = rear;
      return this;
    }

    /** Laser mount and range. */
    public Builder laser(double x, double y, double th, double maxRange) {
      laserX = x;
      laserY = y;
      laserTh = th;
      laserMaxRange = maxRange;
      return this;
    }

    /**
     * Builds the model.
     *
     * @throws IllegalArgumentException if a dimension or factor is not positive, or there are more
     *     than 32 sonar transducers
     */
    public RobotModel build() {
      if (!(lengthFront > 0 && lengthRear > 0 && width > 0)) {
        throw new IllegalArgumentException(
            subtype + ": robot length front/rear and width must be positive");
      }
      if (!(distConv > 0 && angleConv > 0 && velConv > 0 && rangeConv > 0 && vel2Divisor > 0)) {
        throw new IllegalArgumentException(subtype + ": conversion factors must be positive");
      }
      if (numSonar > 32) {
        throw new IllegalArgumentException(
            subtype + ": ARCOS numbers at most 32 sonar transducers, the model has " + numSonar);
      }
      if (!(transVelTop > 0 && rotVelTop > 0 && transAccTop > 0 && rotAccTop > 0)) {
        throw new IllegalArgumentException(subtype + ": top speeds and accelerations must be > 0");
      }
      if (frontBumpers < 0 || frontBumpers > 7 || rearBumpers < 0 || rearBumpers > 7) {
        throw new IllegalArgumentException(subtype + ": a bumper ring has 0..7 segments");
      }
      return new RobotModel(this);
    }
  }
}
