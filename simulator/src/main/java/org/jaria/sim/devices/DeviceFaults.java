package org.jaria.sim.devices;

/**
 * Faults an emulated device shows, as real ones do.
 *
 * @param answerDelayMs how long the device takes before each answer, ms (0: at once)
 * @param dropEveryNthByte loses every n-th byte it sends (0: none), as a noisy line does
 * @param unplugAfterScans after this many scans, sends half of the next one and goes silent with
 *     its connection closed, as when the cable is pulled mid-scan (-1: never)
 */
public record DeviceFaults(long answerDelayMs, int dropEveryNthByte, long unplugAfterScans) {

  /** A healthy device. */
  public static final DeviceFaults NONE = new DeviceFaults(0, 0, -1);

  /** Checks. */
  public DeviceFaults {
    if (answerDelayMs < 0 || dropEveryNthByte < 0) {
      throw new IllegalArgumentException("fault settings must not be negative");
    }
  }

  /** A device that answers after {@code ms}. */
  public DeviceFaults withAnswerDelayMs(long ms) {
    return new DeviceFaults(ms, dropEveryNthByte, unplugAfterScans);
  }

  /** A device that loses every {@code n}-th byte it sends. */
  public DeviceFaults withDropEveryNthByte(int n) {
    return new DeviceFaults(answerDelayMs, n, unplugAfterScans);
  }

  /** A device that is unplugged in the middle of scan {@code n + 1}. */
  public DeviceFaults withUnplugAfterScans(long n) {
    return new DeviceFaults(answerDelayMs, dropEveryNthByte, n);
  }
}
