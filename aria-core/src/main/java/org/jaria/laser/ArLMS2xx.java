package org.jaria.laser;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.function.Consumer;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.connection.ArSerialConnection;
import org.jaria.protocol.DropReason;

/**
 * A SICK LMS-200 family laser (LMS-200, 291, ...) over its binary telegrams (ARIA's {@code
 * ArLMS2xx}). Connecting switches the serial rate from the laser's power-up 9600 baud to the chosen
 * one, sets the field of view and increment, enters installation mode to set the units and
 * reflector bits, then starts continuous output; each scan telegram becomes one scan.
 *
 * <p>Every set-up step but one is sent up to three times, so a telegram damaged on the line costs a
 * retry, not the connection. The exception is the configuration (0x77): the laser stores it in its
 * EEPROM before it answers, which takes a slow unit many seconds, so it is sent once and its answer
 * awaited as long as ARIA does (14 s): a retry would be a second EEPROM write. If the laser does
 * not answer at 9600 baud it is tried at the chosen rate (it still runs there when a program
 * restarts without power-cycling it). Disconnecting stops the output and, as ARIA does, puts the
 * laser back to 9600 baud, so that the next program finds it at its power-up rate.
 */
public class ArLMS2xx extends ArLaser {

  /** Set-up steps sent before giving up. */
  private static final int TRIES = 3;

  /**
   * How long the configuration's answer may take, ms: ARIA's wait. The laser writes the block to
   * its EEPROM first; a slow unit needs more than ten seconds.
   */
  static final long CONFIGURE_WAIT_MS = 14_000;

  /**
   * How long a disconnect waits for each answer (to "stop" and to "9600 baud"), ms: ARIA pauses
   * this long after the stop without waiting for an answer.
   */
  private static final long DISCONNECT_WAIT_MS = 1000;

  private final LmsSettings settings;
  private final LmsReceiver receiver;
  private final LaserInbox<LmsTelegram> inbox;
  // bound once: the reader thread hands it every answer of every scan
  private final Consumer<LmsTelegram> scanTaker = this::takeIfScan;
  private volatile long answerTimeoutMs = 2000;
  private volatile int[] lastReflectance = new int[0];

  /** An LMS-200 with ARIA's default settings (180° by 1°, mm, 38400 baud). */
  public ArLMS2xx() {
    this("lms2xx_1", LmsSettings.DEFAULT);
  }

  /** An LMS-200 set up as {@code settings} says. */
  public ArLMS2xx(String name, LmsSettings settings) {
    super(name, settings.maxRangeMm());
    this.settings = settings;
    this.receiver = new LmsReceiver(true, getDropCounters());
    this.inbox = new LaserInbox<>(receiver::feed, 2048);
  }

  /** How the laser is set up. */
  public LmsSettings getSettings() {
    return settings;
  }

  /** How long to wait for each answer during the set-up, ms (ARIA waits up to 10 s). */
  public void setAnswerTimeoutMs(long ms) {
    answerTimeoutMs = ms;
  }

  /** Reflectance (0–7) of each reading of the last scan. */
  public int[] getLastReflectance() {
    return lastReflectance.clone();
  }

  @Override
  protected int startingBaud(ArSerialConnection serial) {
    return LmsSettings.POWER_UP_BAUD;
  }

  @Override
  protected void handshake(ArDeviceConnection c) throws IOException, InterruptedException {
    receiver.reset();
    inbox.clear();
    if (c instanceof ArSerialConnection serial) {
      switchBaud(c, serial);
    } else {
      ask(c, LmsSettings.modeChange(LmsCommands.MODE_STOP), LmsCommands.MODE_ANSWER, "stop");
    }
    LmsTelegram v = ask(c, settings.variant(), LmsCommands.VARIANT_ANSWER, "field of view");
    if (v.dataLength() < 1 || v.u8(0) != 1) {
      throw new IOException(
          "the laser refused "
              + settings.degrees()
              + "° by "
              + settings.increment()
              + "°: use 180 or 100 degrees by 1, 0.5 (or 0.25 with 100)");
    }
    LmsTelegram install =
        ask(
            c,
            LmsSettings.modeChange(
                LmsCommands.MODE_INSTALL, LmsCommands.PASSWORD.getBytes(StandardCharsets.US_ASCII)),
            LmsCommands.MODE_ANSWER,
            "installation mode");
    checkMode(install, "installation mode");
    configure(c);
    LmsTelegram start =
        ask(
            c,
            LmsSettings.modeChange(LmsCommands.MODE_CONTINUOUS),
            LmsCommands.MODE_ANSWER,
            "continuous output");
    checkMode(start, "continuous output");
  }

  private void switchBaud(ArDeviceConnection c, ArSerialConnection serial)
      throws IOException, InterruptedException {
    int target = settings.baud();
    if (target == serial.getBaud()) {
      ask(c, LmsSettings.modeChange(LmsCommands.MODE_STOP), LmsCommands.MODE_ANSWER, "stop");
      return;
    }
    LmsTelegram answer = tryAsk(c, LmsSettings.baudChange(target), LmsCommands.MODE_ANSWER);
    serial.setBaud(target);
    if (answer == null) {
      // Perhaps it already runs at the target rate (not power-cycled since the last program).
      LmsTelegram stop =
          tryAsk(c, LmsSettings.modeChange(LmsCommands.MODE_STOP), LmsCommands.MODE_ANSWER);
      if (stop == null) {
        throw new IOException(
            "no answer at "
                + LmsSettings.POWER_UP_BAUD
                + " or "
                + target
                + " baud: is the laser powered (it takes about 30 s to start) and on this port?");
      }
    }
  }

  /**
   * Sends the configuration block once and waits up to {@link #CONFIGURE_WAIT_MS} for its answer.
   * Only a refusal (the laser left installation mode) sends it again, after installation mode: the
   * laser did not store that one.
   */
  private void configure(ArDeviceConnection c) throws IOException, InterruptedException {
    byte[] bytes = settings.configuration().encode();
    for (int i = 0; i < TRIES; i++) {
      c.write(bytes, 0, bytes.length);
      LmsTelegram got =
          inbox.await(
              c,
              Math.max(answerTimeoutMs, CONFIGURE_WAIT_MS),
              t ->
                  t.command() == LmsCommands.CONFIGURE_ANSWER
                      || t.command() == LmsCommands.NOT_ACKNOWLEDGED,
              t -> false);
      if (got != null && got.command() == LmsCommands.CONFIGURE_ANSWER) {
        return;
      }
      if (got == null) {
        throw new IOException(
            "no answer to the units and reflector bits request in "
                + Math.max(answerTimeoutMs, CONFIGURE_WAIT_MS)
                + " ms (the laser stores them before it answers): check the laser's power and"
                + " cable");
      }
      checkMode(
          ask(
              c,
              LmsSettings.modeChange(
                  LmsCommands.MODE_INSTALL,
                  LmsCommands.PASSWORD.getBytes(StandardCharsets.US_ASCII)),
              LmsCommands.MODE_ANSWER,
              "installation mode"),
          "installation mode");
    }
    throw new IOException(
        "the laser refused the units and reflector bits " + TRIES + " times: power-cycle it");
  }

  private static void checkMode(LmsTelegram t, String what) throws IOException {
    int status = t.dataLength() < 1 ? -1 : t.u8(0);
    if (status != 0) {
      String why =
          switch (status) {
            case 1 -> "wrong password";
            case 2 -> "LMI fault";
            default -> "status " + status;
          };
      throw new IOException("the laser refused " + what + " (" + why + ")");
    }
  }

  /** Sends {@code t} until the answer {@code answer} arrives (up to {@link #TRIES} times). */
  private LmsTelegram ask(ArDeviceConnection c, LmsTelegram t, int answer, String what)
      throws IOException, InterruptedException {
    LmsTelegram got = tryAsk(c, t, answer);
    if (got == null) {
      throw new IOException(
          "no answer to the "
              + what
              + " request after "
              + TRIES
              + " tries of "
              + answerTimeoutMs
              + " ms: check the laser's power, cable and baud rate");
    }
    return got;
  }

  private LmsTelegram tryAsk(ArDeviceConnection c, LmsTelegram t, int answer)
      throws IOException, InterruptedException {
    byte[] bytes = t.encode();
    for (int i = 0; i < TRIES; i++) {
      c.write(bytes, 0, bytes.length);
      LmsTelegram got = await(c, answer);
      if (got != null) {
        return got;
      }
    }
    return null;
  }

  /** Reads until a telegram with code {@code answer} arrives (others are dropped) or time is up. */
  private LmsTelegram await(ArDeviceConnection c, int answer)
      throws IOException, InterruptedException {
    return inbox.await(
        c,
        answerTimeoutMs,
        t -> t.command() == answer,
        t -> t.command() == LmsCommands.NOT_ACKNOWLEDGED);
  }

  @Override
  protected void pump(ArDeviceConnection c, long waitMs) throws IOException {
    inbox.drain(c, waitMs, scanTaker);
  }

  private void takeIfScan(LmsTelegram t) {
    if (t.command() == LmsCommands.SCAN) {
      takeScan(t);
    }
  }

  private void takeScan(LmsTelegram t) {
    LmsScanData d;
    try {
      d = LmsScanData.decode(t, settings.reflectorBits());
    } catch (IllegalArgumentException e) {
      getDropCounters().drop(DropReason.MALFORMED, e.getMessage());
      return;
    }
    if (d.size() != settings.readingCount()) {
      getDropCounters()
          .drop(
              DropReason.MALFORMED,
              "scan of " + d.size() + " readings, expected " + settings.readingCount());
      return;
    }
    double[] angles = new double[d.size()];
    double[] ranges = new double[d.size()];
    double first = -settings.degrees() / 2.0;
    for (int i = 0; i < angles.length; i++) {
      angles[i] = first + i * settings.increment();
      ranges[i] = d.distance(i);
    }
    lastReflectance = d.reflectance();
    publish(angles, ranges);
  }

  /**
   * Stops the continuous output and, on a serial port at another rate, puts the laser back to its
   * power-up 9600 baud as ARIA does (the next program, ARIA's included, then finds it there at
   * once). Each step waits for the laser's answer, at most {@link #DISCONNECT_WAIT_MS}, where ARIA
   * pauses for that long.
   */
  @Override
  protected void stopMeasuring(ArDeviceConnection c) throws IOException {
    try {
      byte[] stop = LmsSettings.modeChange(LmsCommands.MODE_STOP).encode();
      c.write(stop, 0, stop.length);
      awaitQuietly(c, LmsCommands.MODE_ANSWER); // scans still on the way are dropped meanwhile
      if (c instanceof ArSerialConnection serial && serial.getBaud() != LmsSettings.POWER_UP_BAUD) {
        byte[] slow = LmsSettings.baudChange(LmsSettings.POWER_UP_BAUD).encode();
        c.write(slow, 0, slow.length);
        awaitQuietly(c, LmsCommands.MODE_ANSWER);
        serial.setBaud(LmsSettings.POWER_UP_BAUD);
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
    }
  }

  private void awaitQuietly(ArDeviceConnection c, int answer)
      throws IOException, InterruptedException {
    inbox.await(c, DISCONNECT_WAIT_MS, t -> t.command() == answer, t -> false);
  }
}
