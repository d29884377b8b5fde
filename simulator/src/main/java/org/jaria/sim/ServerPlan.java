package org.jaria.sim;

/**
 * Which TCP port each robot factory and each robot of a MobileSim-style command line gets, as
 * MobileSim hands them out: the factories ({@code -R}) first, on the base port ({@code -p}, 8101 by
 * default) and the ports after it, one each; then the robots ({@code -r}) on the ports after the
 * factories'. (MobileSim starts its robots on the base port too, finds the factories there and
 * moves on to the next free port; the result is the same, without the retries.) A base port of 0
 * gives every one any free port.
 *
 * @param basePort the first port (0: any free port for all)
 * @param factories how many robot factories
 * @param robots how many robots with their own port
 */
public record ServerPlan(int basePort, int factories, int robots) {

  /**
   * Checks the counts and that the last port exists.
   *
   * @throws IllegalArgumentException saying what is wrong
   */
  public ServerPlan {
    if (factories < 0 || robots < 0) {
      throw new IllegalArgumentException("counts cannot be negative");
    }
    if (basePort < 0 || basePort > 65535) {
      throw new IllegalArgumentException("the port must be 0..65535, was " + basePort);
    }
    if (basePort > 0 && basePort + factories + robots - 1 > 65535) {
      throw new IllegalArgumentException(
          (factories + robots)
              + " ports from "
              + basePort
              + " go beyond 65535: choose a lower port with -p");
    }
  }

  /** The port of factory {@code i} (0 first). */
  public int factoryPort(int i) {
    if (i < 0 || i >= factories) {
      throw new IndexOutOfBoundsException("no factory " + i + " of " + factories);
    }
    return basePort == 0 ? 0 : basePort + i;
  }

  /** The port of robot {@code i} (0 first). */
  public int robotPort(int i) {
    if (i < 0 || i >= robots) {
      throw new IndexOutOfBoundsException("no robot " + i + " of " + robots);
    }
    return basePort == 0 ? 0 : basePort + factories + i;
  }
}
