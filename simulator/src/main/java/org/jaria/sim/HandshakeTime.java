package org.jaria.sim;

/**
 * How long a network client has for its handshake, in the simulated time the sessions measure.
 *
 * <p>The limit is real time: the client is a program running at its own pace, however fast the
 * world runs. A world running ten times faster than real time therefore gives it ten times as many
 * simulated milliseconds; otherwise {@code --speedup 10} would leave a program that takes a few
 * hundred milliseconds to start (a Java source file compiled at launch, a loaded machine) 200 ms to
 * connect. A world stepped by hand (tests) or running as fast as it can has no real pace to follow,
 * so the limit is taken as simulated time there.
 */
final class HandshakeTime {

  private HandshakeTime() {}

  /**
   * The handshake limit in simulated ms for a limit of {@code realMillis} and a world running
   * {@code speedup} times faster than real time.
   */
  static int simulatedMillis(int realMillis, double speedup) {
    if (!(speedup > 1)) {
      return realMillis;
    }
    return (int) Math.min(Integer.MAX_VALUE, Math.round(realMillis * speedup));
  }
}
