package org.jaria.sim.robot;

import java.util.random.RandomGenerator;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.sim.OdometryError;
import org.jaria.sim.SonarOptions;
import org.jaria.sim.serial.AuxPort;
import org.jaria.sim.serial.AuxSerialDevice;
import org.jaria.sim.serial.Vcc4Camera;
import org.jaria.sim.world.Contact;
import org.jaria.sim.world.Footprint;
import org.jaria.sim.world.WorldGeometry;

/**
 * One simulated robot's physical state and devices: the true pose, the drive, odometry, sonar,
 * laser, gyro, gripper and I/O. {@link #physics} advances it by one tick: the drive moves the
 * footprint unless it would overlap something, in which case the robot stops, its stall bits and
 * the bumper segment that touched are set; then the sensors sample the new pose.
 *
 * <p>Not thread-safe: owned by the world thread (the world's lock guards every access).
 */
public final class RobotBody {

  /** Stall bit of the left motor. */
  public static final int STALL_LEFT = 1;

  /** Stall bit of the right motor. */
  public static final int STALL_RIGHT = 1 << 8;

  /**
   * First bit of the front bumper ring. ARIA reads the front ring from the high byte of the stall
   * word (bumper i at bit 9 + i) and the rear ring from the low byte (bit 1 + i).
   */
  public static final int FRONT_BUMPER_SHIFT = 9;

  /** How far a bump ring gives before the robot's body touches, mm. */
  public static final double BUMPER_TRAVEL = 40;

  /** First bit of the rear bumper ring. */
  public static final int REAR_BUMPER_SHIFT = 1;

  /** Arc covered by each bumper ring, degrees (ARIA's ArBumpers default). */
  public static final double BUMPER_ARC = 135;

  private final int index;
  private final String name;
  private final RobotModel model;
  private final Footprint footprint;
  private final Footprint candidate;

  /** The footprint with the front ring's travel added: contact there presses it going forward. */
  private final Footprint frontZone;

  /** The same for the rear ring, going backwards. */
  private final Footprint rearZone;

  private int latchedBits;
  private final Contact contact = new Contact();
  private final Contact here = new Contact();
  private final MotionController motion;
  private final Odometry odometry;
  private final SonarModel sonar;
  private final LaserModel laser;
  private final GyroModel gyro;
  private final Gripper gripper;
  private final RobotIo io;
  private final SimProfile profile;

  /**
   * AUX1..AUX3; a Canon VC-C4 on AUX1 (where a Pioneer's PTZ camera is wired) unless {@link
   * #setAuxDevice} puts another device there.
   */
  private final AuxPort[] auxPorts = {
    new AuxPort(1, new Vcc4Camera()), new AuxPort(2, null), new AuxPort(3, null)
  };

  private boolean srisimCompat;

  private ArPose startPose;
  private double x;
  private double y;
  private double th;
  private int stallBits;
  private int bumpStall;
  private double lastDs;
  private double lastDth;
  private double travelled;

  /**
   * A robot at {@code start}.
   *
   * @param index the robot's number in its world (for ray and collision exclusion)
   * @param rngs seeded sources: odometry, sonar, laser, gyro, in that order
   * @param hasLaser whether it carries a laser (else {@link #laser()} is null)
   * @param hasGyro whether it carries a gyro (else {@link #gyro()} is null)
   * @param hasGripper whether it carries a gripper (else {@link #gripper()} is null)
   */
  public RobotBody(
      int index,
      String name,
      RobotModel model,
      ArPose start,
      SonarOptions sonarOptions,
      OdometryError odometryError,
      RandomGenerator[] rngs,
      boolean hasLaser,
      boolean hasGyro,
      boolean hasGripper) {
    this(
        index,
        name,
        model,
        start,
        sonarOptions,
        odometryError,
        rngs,
        hasLaser,
        hasGyro,
        hasGripper,
        SimProfile.PIONEER);
  }

  /**
   * A robot at {@code start} that behaves as {@code profile} says (the other parameters as above).
   */
  public RobotBody(
      int index,
      String name,
      RobotModel model,
      ArPose start,
      SonarOptions sonarOptions,
      OdometryError odometryError,
      RandomGenerator[] rngs,
      boolean hasLaser,
      boolean hasGyro,
      boolean hasGripper,
      SimProfile profile) {
    this.index = index;
    this.name = name;
    this.model = model;
    this.footprint = new Footprint(model.getLengthFront(), model.getLengthRear(), model.getWidth());
    this.candidate = footprint.copy();
    this.frontZone =
        new Footprint(
            model.getLengthFront() + BUMPER_TRAVEL, model.getLengthRear(), model.getWidth());
    this.rearZone =
        new Footprint(
            model.getLengthFront(), model.getLengthRear() + BUMPER_TRAVEL, model.getWidth());
    this.profile = profile;
    this.motion = new MotionController(model, profile);
    this.io = profile == SimProfile.MOBILESIM ? new RobotIo(0xFF, 0xFF) : new RobotIo();
    this.odometry = new Odometry(model.getTrackWidth(), odometryError, rngs[0]);
    this.sonar = new SonarModel(model, sonarOptions, rngs[1]);
    this.laser = hasLaser ? new LaserModel(model, rngs[2], profile == SimProfile.MOBILESIM) : null;
    this.gyro = hasGyro ? new GyroModel(model.getGyroScaler(), rngs[3]) : null;
    this.gripper = hasGripper ? new Gripper() : null;
    this.startPose = start;
    setTruePose(start);
    if (profile.motorsEnabledAtStart()) {
      motion.enableMotors(true);
    }
  }

  /**
   * Advances one tick of {@code dt} seconds at simulated time {@code now} (ns).
   *
   * @param world everything the robot can run into or see
   */
  public void physics(double dt, WorldGeometry world, long now) {
    motion.update(dt, odometry.getTh());
    double ds = motion.lastDistance();
    double dth = motion.lastRotation();
    stallBits = 0;
    if (ds != 0 || dth != 0) {
      double mid = Math.toRadians(th + dth / 2);
      double nx = x + ds * Math.cos(mid);
      double ny = y + ds * Math.sin(mid);
      candidate.place(nx, ny, Math.toRadians(th + dth));
      if (world.collides(candidate, index, contact) && !escaping(world)) {
        boolean rotationFree = false;
        if (dth != 0) {
          candidate.place(x, y, Math.toRadians(th + dth));
          rotationFree = !world.collides(candidate, index, here);
        }
        motion.blocked(true, !rotationFree);
        ds = 0;
        if (!rotationFree) {
          dth = 0;
        }
        stallBits = STALL_LEFT | STALL_RIGHT | bumperBits(contact.x, contact.y);
        applyBumpStall();
      } else if (ds != 0) {
        // The bump ring gives before the body touches: its switches close while the robot still
        // moves, as on a real robot, so bumper-driven behaviours see the speed of the impact.
        Footprint zone = ds > 0 ? frontZone : rearZone;
        zone.place(nx, ny, Math.toRadians(th + dth));
        if (world.collides(zone, index, contact) && !escaping(world)) {
          stallBits = bumperBits(contact.x, contact.y);
          motion.cushioned(dt);
          if (motion.isPushing()) {
            // Pressed against it and not getting anywhere: the motors stall.
            stallBits |= STALL_LEFT | STALL_RIGHT;
          }
          applyBumpStall();
        }
      }
      if (ds != 0 || dth != 0) {
        double m = Math.toRadians(th + dth / 2);
        x += ds * Math.cos(m);
        y += ds * Math.sin(m);
        th = ArMath.fixAngle(th + dth);
        footprint.place(x, y, Math.toRadians(th));
      }
    }
    latchedBits |= stallBits;
    travelled += Math.abs(ds);
    lastDs = ds;
    lastDth = dth;
    double dtMs = dt * 1000;
    odometry.update(ds, dth, dtMs);
    motion.measured(odometry.lastMeasured());
    if (gyro != null) {
      gyro.tick(dtMs, dth);
    }
    if (gripper != null) {
      gripper.tick(dtMs);
    }
    sonar.tick(dtMs, x, y, Math.toRadians(th), world, index, now);
  }

  /**
   * Whether the robot already overlaps something where it stands and the candidate pose takes it
   * away from the contact (so a robot placed into an obstacle can drive out).
   */
  private boolean escaping(WorldGeometry world) {
    double cand = contact.distSq;
    if (!world.collides(footprint, index, here)) {
      return false;
    }
    double ddx = here.x - x;
    double ddy = here.y - y;
    double before = ddx * ddx + ddy * ddy;
    return cand > before + 1e-9;
  }

  private void applyBumpStall() {
    boolean front = ((stallBits >> FRONT_BUMPER_SHIFT) & 0x7F) != 0;
    boolean rear = ((stallBits >> REAR_BUMPER_SHIFT) & 0x7F) != 0;
    if ((front && (bumpStall & 1) != 0) || (rear && (bumpStall & 2) != 0)) {
      motion.stop();
    }
  }

  /** The bumper bits for a contact at world point (cx, cy). */
  int bumperBits(double cx, double cy) {
    double rad = Math.toRadians(th);
    double c = Math.cos(rad);
    double s = Math.sin(rad);
    double lx = c * (cx - x) + s * (cy - y);
    double ly = -s * (cx - x) + c * (cy - y);
    double alpha = Math.toDegrees(Math.atan2(ly, lx));
    if (lx >= 0) {
      int n = model.getNumFrontBumpers();
      return n == 0 ? 0 : 1 << (FRONT_BUMPER_SHIFT + segment(alpha, n));
    }
    int n = model.getNumRearBumpers();
    return n == 0 ? 0 : 1 << (REAR_BUMPER_SHIFT + segment(ArMath.fixAngle(alpha - 180), n));
  }

  /** Bumper segment (0 = leftmost seen from the ring's own direction) for a contact angle. */
  private static int segment(double angleDeg, int n) {
    double w = BUMPER_ARC / n;
    int i = (int) Math.floor((BUMPER_ARC / 2 - angleDeg) / w);
    return Math.max(0, Math.min(n - 1, i));
  }

  /**
   * Starts the robot as a fresh session does: stopped, defaults, odometry at 0,0,0; a real
   * Pioneer's motors off (MobileSim leaves them as they are: on when the robot was made, off after
   * a session ended).
   */
  public void openSession() {
    motion.resetSettings();
    if (profile == SimProfile.MOBILESIM) {
      motion.halt();
    } else {
      motion.enableMotors(false);
    }
    odometry.resetSettings();
    odometry.setPose(0, 0, 0);
    sonar.resetSettings();
    sonar.setAllEnabled(true);
    io.resetSettings();
    for (AuxPort p : auxPorts) {
      p.request(0);
    }
    bumpStall = 0;
    if (laser != null) {
      laser.resetSettings();
    }
    if (gyro != null) {
      gyro.setStreaming(false);
    }
  }

  /** Ends a session (CLOSE, client gone): stops dead, motors and sonar off. */
  public void closeSession() {
    motion.enableMotors(false);
    sonar.setAllEnabled(false);
    sonar.clearPending();
    if (gyro != null) {
      gyro.setStreaming(false);
    }
  }

  /** Plugs {@code device} (null: nothing) into auxiliary serial port {@code n} (1..3). */
  public void setAuxDevice(int n, AuxSerialDevice device) {
    auxPort(n); // checks n
    auxPorts[n - 1] = new AuxPort(n, device);
  }

  /** Auxiliary serial port {@code n} (1..3). */
  public AuxPort auxPort(int n) {
    if (n < 1 || n > auxPorts.length) {
      throw new IllegalArgumentException("AUX port " + n + " not in 1..3");
    }
    return auxPorts[n - 1];
  }

  /**
   * Whether the robot also takes SRISim's old commands (62 exit, 66/67 true x/y, 69 back to the
   * start), as MobileSim's {@code --srisim-compat}.
   */
  public boolean isSrisimCompat() {
    return srisimCompat;
  }

  /** Turns SRISim's old commands on or off (see {@link #isSrisimCompat()}). */
  public void setSrisimCompat(boolean on) {
    srisimCompat = on;
  }

  /** Moves the robot to a true pose; odometry is not touched (SIM_SET_POSE). */
  public void setTruePose(ArPose p) {
    x = p.x();
    y = p.y();
    th = p.th();
    footprint.place(x, y, Math.toRadians(th));
  }

  /** SIM_RESET: back to the start pose, odometry 0,0,0. */
  public void resetToStart() {
    setTruePose(startPose);
    odometry.setPose(0, 0, 0);
  }

  /** Changes where SIM_RESET returns to. */
  public void setStartPose(ArPose p) {
    startPose = p;
  }

  /** The true pose. */
  public ArPose getTruePose() {
    return new ArPose(x, y, th);
  }

  /** True x, mm. */
  public double trueX() {
    return x;
  }

  /** True y, mm. */
  public double trueY() {
    return y;
  }

  /** True heading, degrees. */
  public double trueTh() {
    return th;
  }

  /** Where SIM_RESET returns to. */
  public ArPose getStartPose() {
    return startPose;
  }

  /** Odometry pose. */
  public ArPose getOdometryPose() {
    return new ArPose(odometry.getX(), odometry.getY(), odometry.getTh());
  }

  /**
   * Stall and bumper bits seen in any tick since the last call, then forgotten: what the next SIP
   * reports, so a bump between two SIPs is not missed.
   */
  public int takeLatchedStallBits() {
    int b = latchedBits | stallBits;
    latchedBits = 0;
    return b;
  }

  /** Stall and bumper bits of the last tick. */
  public int getStallBits() {
    return stallBits;
  }

  /** BUMPSTALL: 0 none, 1 front, 2 rear, 3 both. */
  public void setBumpStall(int mode) {
    bumpStall = mode & 3;
  }

  /** Distance driven since the robot was made (forwards and backwards counted alike), mm. */
  public double travelled() {
    return travelled;
  }

  /** Whose behaviour the robot copies: MobileSim's or a real Pioneer's. */
  public SimProfile profile() {
    return profile;
  }

  /** Distance actually travelled in the last tick, mm. */
  public double lastDistance() {
    return lastDs;
  }

  /** Rotation actually made in the last tick, degrees. */
  public double lastRotation() {
    return lastDth;
  }

  /** The robot's number in its world. */
  public int index() {
    return index;
  }

  /** The robot's name. */
  public String name() {
    return name;
  }

  /** The robot's model. */
  public RobotModel model() {
    return model;
  }

  /** The placed footprint (world frame). */
  public Footprint footprint() {
    return footprint;
  }

  /** The drive. */
  public MotionController motion() {
    return motion;
  }

  /** The encoders and odometry. */
  public Odometry odometry() {
    return odometry;
  }

  /** The sonar. */
  public SonarModel sonar() {
    return sonar;
  }

  /** The laser, or null if the robot has none. */
  public LaserModel laser() {
    return laser;
  }

  /** The gyro, or null if the robot has none. */
  public GyroModel gyro() {
    return gyro;
  }

  /** The gripper, or null if the robot has none. */
  public Gripper gripper() {
    return gripper;
  }

  /** Digital and analog I/O, battery, buzzer, compass mode. */
  public RobotIo io() {
    return io;
  }
}
