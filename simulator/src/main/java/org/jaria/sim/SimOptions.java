package org.jaria.sim;

import java.time.Duration;
import org.jaria.sim.robot.SimProfile;

/**
 * World-wide settings of a simulation. Build with {@link #builder()}; {@link #defaults()} gives
 * MobileSim-like values.
 *
 * @param seed seed of every random number in the world (noise, odometry error, gyro); the same seed
 *     and the same commands give the same run
 * @param tick simulated time of one physics step (default 10 ms)
 * @param sipCycleMillis time between two SIPs, ms (default 100)
 * @param watchdogMillis time without commands after which a robot stops, ms (default 2000; 0 off)
 * @param watchdogWarnOnly whether the watchdog only logs a warning instead of stopping the robot
 * @param sonar how sonar sees the world
 * @param odometryError how odometry errs
 * @param basePort TCP port of the first robot (default 8101; each further robot takes the next; 0
 *     lets the system pick free ports)
 * @param server how the robots' ports treat their clients (timeouts, ignored commands, map folder)
 * @param profile whose robot the simulator copies: a real Pioneer's (the default) or MobileSim's
 *     (see {@link SimProfile})
 */
public record SimOptions(
    long seed,
    Duration tick,
    int sipCycleMillis,
    int watchdogMillis,
    boolean watchdogWarnOnly,
    SonarOptions sonar,
    OdometryError odometryError,
    int basePort,
    SimServerOptions server,
    SimProfile profile) {

  /** MobileSim's first robot port. */
  public static final int DEFAULT_PORT = 8101;

  /** Checks the values. */
  public SimOptions {
    if (tick == null
        || tick.isNegative()
        || tick.isZero()
        || tick.compareTo(Duration.ofSeconds(1)) > 0) {
      throw new IllegalArgumentException("tick must be between 0 and 1 s, was " + tick);
    }
    if (sipCycleMillis < 1 || sipCycleMillis > 255) {
      throw new IllegalArgumentException(
          "SIP cycle must be 1..255 ms (CONFIGpac carries it in a byte), was " + sipCycleMillis);
    }
    if (watchdogMillis < 0 || watchdogMillis > 65535) {
      throw new IllegalArgumentException("watchdog must be 0..65535 ms, was " + watchdogMillis);
    }
    if (sonar == null || odometryError == null) {
      throw new IllegalArgumentException("sonar and odometry error options must not be null");
    }
    if (basePort < 0 || basePort > 65535) {
      throw new IllegalArgumentException("port must be 0..65535, was " + basePort);
    }
    if (server == null) {
      throw new IllegalArgumentException("server options must not be null");
    }
    if (profile == null) {
      throw new IllegalArgumentException("the profile must not be null: MOBILESIM or PIONEER");
    }
  }

  /**
   * Defaults: seed 1, 10 ms ticks, 100 ms SIPs, 2 s watchdog, the {@link SimProfile#PIONEER
   * pioneer} profile with its sonar and exact odometry.
   */
  public static SimOptions defaults() {
    return builder().build();
  }

  /** A builder starting from the defaults. */
  public static Builder builder() {
    return new Builder();
  }

  /** A builder starting from these options. */
  public Builder toBuilder() {
    Builder b = new Builder();
    b.seed = seed;
    b.tick = tick;
    b.sipCycleMillis = sipCycleMillis;
    b.watchdogMillis = watchdogMillis;
    b.watchdogWarnOnly = watchdogWarnOnly;
    b.sonar = sonar;
    b.odometryError = odometryError;
    b.basePort = basePort;
    b.server = server;
    b.profile = profile;
    return b;
  }

  /** Builds {@link SimOptions}. */
  public static final class Builder {
    private long seed = 1;
    private Duration tick = Duration.ofMillis(10);
    private int sipCycleMillis = 100;
    private int watchdogMillis = 2000;
    private boolean watchdogWarnOnly;
    private SonarOptions sonar = SonarOptions.DEFAULTS;
    private OdometryError odometryError = OdometryError.NONE;
    private int basePort = DEFAULT_PORT;
    private SimServerOptions server = SimServerOptions.DEFAULTS;
    private SimProfile profile = SimProfile.PIONEER;

    private Builder() {}

    /**
     * Whose robot to copy; also sets the sonar and the odometry error to the profile's (call {@link
     * #sonar} or {@link #odometryError} after this to change them).
     */
    public Builder profile(SimProfile p) {
      profile = p;
      if (p != null) {
        sonar = p.sonar();
        odometryError = p.odometryError();
      }
      return this;
    }

    /** Random seed. */
    public Builder seed(long s) {
      seed = s;
      return this;
    }

    /** Physics step. */
    public Builder tick(Duration d) {
      tick = d;
      return this;
    }

    /** Physics step, ms. */
    public Builder tickMillis(long ms) {
      return tick(Duration.ofMillis(ms));
    }

    /** SIP cycle, ms. */
    public Builder sipCycleMillis(int ms) {
      sipCycleMillis = ms;
      return this;
    }

    /** Watchdog time, ms (0 = off). */
    public Builder watchdogMillis(int ms) {
      watchdogMillis = ms;
      return this;
    }

    /** Watchdog only warns. */
    public Builder watchdogWarnOnly(boolean b) {
      watchdogWarnOnly = b;
      return this;
    }

    /** Sonar model. */
    public Builder sonar(SonarOptions s) {
      sonar = s;
      return this;
    }

    /** Odometry error model. */
    public Builder odometryError(OdometryError e) {
      odometryError = e;
      return this;
    }

    /** Port of the first robot (0 = any free port). */
    public Builder basePort(int p) {
      basePort = p;
      return this;
    }

    /** How the robots' ports treat their clients. */
    public Builder server(SimServerOptions s) {
      server = s;
      return this;
    }

    /** The options. */
    public SimOptions build() {
      return new SimOptions(
          seed,
          tick,
          sipCycleMillis,
          watchdogMillis,
          watchdogWarnOnly,
          sonar,
          odometryError,
          basePort,
          server,
          profile);
    }
  }
}
