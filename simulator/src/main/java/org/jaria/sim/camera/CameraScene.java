package org.jaria.sim.camera;

/**
 * What a {@link SimCamera} looks at: the walls, obstacles and robots a ray meets, and the coloured
 * objects. The simulator's world is one ({@code SimWorld} implements this).
 *
 * <p>Why an interface of this package: the world holds its {@link ColoredObjects}, so it depends on
 * this package; the camera reads the world only through this interface and {@link CameraMount}, so
 * this package does not depend back on the world and the two do not form a loop.
 */
public interface CameraScene {

  /**
   * Ground truth: the distance from (x, y) along {@code thDeg} to the nearest wall, obstacle or
   * robot other than robot number {@code self} (the camera's own, whose outline it sits in), or
   * {@link Double#POSITIVE_INFINITY} beyond {@code maxRange}. Millimetres and degrees.
   */
  double castRay(double x, double y, double thDeg, double maxRange, int self);

  /** The coloured objects the camera shows. */
  ColoredObjects coloredObjects();

  /** The seed of the world's random numbers; the camera's pixel noise is drawn from it. */
  long seed();
}
