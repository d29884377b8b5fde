package org.jaria.sim.world;

/**
 * The result of one ray cast, filled in place so that casting allocates nothing. One instance
 * belongs to one caller (the world thread reuses a few).
 */
public final class RayHit {

  /** Distance from the ray origin to the hit, mm; {@link Double#POSITIVE_INFINITY} if none. */
  public double distance = Double.POSITIVE_INFINITY;

  /** Cosine of the angle between the ray and the surface normal (1 head on, 0 grazing). */
  public double cosIncidence;

  /** What was hit: a map line, a map point, an injected obstacle or another robot. */
  public HitKind kind = HitKind.NONE;

  /** Number of the robot that was hit (only for {@link HitKind#ROBOT}), else -1. */
  public int robot = -1;

  /** Whether the ray hit anything within range. */
  public boolean hit() {
    return kind != HitKind.NONE;
  }

  /** Forgets the previous result. */
  public void reset() {
    distance = Double.POSITIVE_INFINITY;
    cosIncidence = 0;
    kind = HitKind.NONE;
    robot = -1;
  }

  /** What a ray or a robot can run into. */
  public enum HitKind {
    /** Nothing within range. */
    NONE,
    /** A LINES entry of the map. */
    LINE,
    /** A DATA point of the map. */
    POINT,
    /** An obstacle injected through the API. */
    OBSTACLE,
    /** Another simulated robot. */
    ROBOT
  }
}
