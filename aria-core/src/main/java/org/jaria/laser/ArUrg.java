package org.jaria.laser;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.connection.ArSerialConnection;
import org.jaria.protocol.DropReason;

/**
 * A Hokuyo URG laser over SCIP 2.0 (ARIA's {@code ArUrg_2_0}, which ARIA programs also reach as
 * {@code ArUrg}). Connecting switches the device to SCIP 2.0, asks for its version (VV) and
 * parameters (PP), optionally changes the serial rate (SS), switches the laser on (BM) and starts
 * continuous measurement of 3-character distances (MD); each MD answer becomes one scan.
 *
 * <p>Distances below the device's minimum (DMIN) are its error codes and count as "no echo". Every
 * request is sent up to three times.
 */
public class ArUrg extends ArLaser {

  private static final int TRIES = 3;

  private final UrgSettings settings;
  private final ScipReceiver receiver;
  private final LaserInbox<ScipBlock> inbox;
  // bound once: the reader thread hands it every answer of every scan
  private final Consumer<ScipBlock> scanTaker = this::takeIfScan;
  private volatile long answerTimeoutMs = 2000;
  private volatile UrgParams params;
  private volatile Map<String, String> version = Map.of();
  private int firstStep;
  private int lastStep;

  /** A URG read from −90° to 90°. */
  public ArUrg() {
    this("urg_1", UrgSettings.DEFAULT);
  }

  /** A URG read as {@code settings} says. */
  public ArUrg(String name, UrgSettings settings) {
    super(name, UrgParams.URG_04LX.maxRange());
    this.settings = settings;
    this.receiver = new ScipReceiver(getDropCounters());
    this.inbox = new LaserInbox<>(receiver::feed, 4096);
  }

  /** How the laser is read. */
  public UrgSettings getSettings() {
    return settings;
  }

  /** What the device said about itself (PP), once connected; null before. */
  public UrgParams getParams() {
    return params;
  }

  /** The device's VV answer (VEND, PROD, FIRM, PROT, SERI), once connected. */
  public Map<String, String> getVersion() {
    return version;
  }

  /** How long to wait for each answer during the set-up, ms. */
  public void setAnswerTimeoutMs(long ms) {
    answerTimeoutMs = ms;
  }

  @Override
  protected int startingBaud(ArSerialConnection serial) {
    return settings.startingBaud();
  }

  @Override
  protected void handshake(ArDeviceConnection c) throws IOException, InterruptedException {
    receiver.reset();
    inbox.clear();
    // In SCIP 1.1 this switches to 2.0; in 2.0 it is answered "already". Either way, any answer.
    if (tryAsk(c, "SCIP2.0") == null) {
      throw new IOException(
          "no answer to SCIP2.0: is the URG powered, on this port, and at "
              + settings.startingBaud()
              + " baud?");
    }
    ask(c, "QT", "laser off");
    version = ask(c, "VV", "version").info();
    UrgParams p;
    try {
      p = UrgParams.of(ask(c, "PP", "parameters").info());
    } catch (IllegalArgumentException e) {
      throw new IOException(e.getMessage(), e);
    }
    params = p;
    setMaxRange(p.maxRange());
    if (c instanceof ArSerialConnection serial && settings.baud() != serial.getBaud()) {
      String ss = String.format(Locale.ROOT, "SS%06d", settings.baud());
      String status = ask(c, ss, "baud rate change").status();
      if (!status.equals("00") && !status.equals("03")) {
        throw new IOException(
            "the URG refused " + settings.baud() + " baud (status " + status + ")");
      }
      serial.setBaud(settings.baud());
    }
    String on = ask(c, "BM", "laser on").status();
    if (!on.equals("00") && !on.equals("02")) {
      throw new IOException("the URG could not switch its laser on (status " + on + ")");
    }
    firstStep = p.stepOf(settings.startDeg());
    lastStep = p.stepOf(settings.endDeg());
    String md =
        String.format(
            Locale.ROOT,
            "MD%04d%04d%02d%01d%02d",
            firstStep,
            lastStep,
            settings.clusterCount(),
            0,
            0);
    String status = ask(c, md, "continuous measurement").status();
    if (!status.equals("00")) {
      throw new IOException("the URG refused " + md + " (status " + status + ")");
    }
  }

  private ScipBlock ask(ArDeviceConnection c, String command, String what)
      throws IOException, InterruptedException {
    ScipBlock b = tryAsk(c, command);
    if (b == null) {
      throw new IOException(
          "no answer to the "
              + what
              + " request ("
              + command
              + ") after "
              + TRIES
              + " tries of "
              + answerTimeoutMs
              + " ms: check the URG's power, cable and baud rate");
    }
    return b;
  }

  private ScipBlock tryAsk(ArDeviceConnection c, String command)
      throws IOException, InterruptedException {
    byte[] bytes = (command + "\n").getBytes(StandardCharsets.US_ASCII);
    for (int i = 0; i < TRIES; i++) {
      c.write(bytes, 0, bytes.length);
      ScipBlock b = await(c, command);
      if (b != null) {
        return b;
      }
    }
    return null;
  }

  private ScipBlock await(ArDeviceConnection c, String command)
      throws IOException, InterruptedException {
    return inbox.await(c, answerTimeoutMs, b -> b.echo().equals(command), b -> false);
  }

  @Override
  protected void pump(ArDeviceConnection c, long waitMs) throws IOException {
    inbox.drain(c, waitMs, scanTaker);
  }

  private void takeIfScan(ScipBlock b) {
    if (b.echo().startsWith("MD") && b.status().equals("99")) {
      takeScan(b);
    }
  }

  private void takeScan(ScipBlock b) {
    UrgParams p = params;
    int cluster = settings.clusterCount();
    int expected = (lastStep - firstStep) / cluster + 1;
    int[] raw;
    try {
      // Line 2 is the time stamp; the distances follow.
      raw = Scip.decodeAll(b.joinedData(3), 3);
    } catch (IllegalArgumentException e) {
      getDropCounters().drop(DropReason.BAD_CHECKSUM, e.getMessage());
      return;
    }
    if (raw.length != expected) {
      getDropCounters().drop(DropReason.MALFORMED, raw.length + " distances, expected " + expected);
      return;
    }
    double[] angles = new double[raw.length];
    double[] ranges = new double[raw.length];
    for (int i = 0; i < raw.length; i++) {
      angles[i] = p.angleOf(firstStep + i * cluster + (cluster - 1) / 2.0);
      ranges[i] = raw[i] < p.minRange() ? 0 : raw[i];
    }
    publish(angles, ranges);
  }

  @Override
  protected void stopMeasuring(ArDeviceConnection c) throws IOException {
    byte[] qt = "QT\n".getBytes(StandardCharsets.US_ASCII);
    c.write(qt, 0, qt.length);
  }
}
