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
 * <p>With {@link #setProtocol setProtocol(Protocol.SCIP_1_1)} it speaks SCIP 1.1 instead, as ARIA's
 * {@code ArUrg} does (see {@link Scip11}): the version (V), the serial rate (S), then one distance
 * request (G, 2-character distances up to 4095 mm) per scan, the next sent as soon as a scan
 * arrives (and again if none comes within the answer timeout).
 *
 * <p>Distances below the device's minimum (DMIN) are its error codes and count as "no echo". Every
 * request is sent up to three times.
 */
public class ArUrg extends ArLaser {

  /** The command language spoken to the device. */
  public enum Protocol {
    /** SCIP 2.0 (the default): continuous measurement with MD. */
    SCIP_2_0,
    /** SCIP 1.1, ARIA's {@code ArUrg}: a G request per scan. */
    SCIP_1_1
  }

  private static final int TRIES = 3;

  private final UrgSettings settings;
  private final ScipReceiver receiver;
  private final LaserInbox<ScipBlock> inbox;
  // bound once: the reader thread hands it every answer of every scan
  private final Consumer<ScipBlock> scanTaker = this::takeIfScan;
  private volatile long answerTimeoutMs = 2000;
  private volatile UrgParams params;
  private volatile Map<String, String> version = Map.of();
  private volatile int firstStep;
  private volatile int lastStep;
  private volatile Protocol protocol = Protocol.SCIP_2_0;
  private volatile ArDeviceConnection scip11Connection;
  private volatile String scip11Request = "";
  private volatile long lastRequestNanos;

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

  /** Chooses the protocol (before connecting). */
  public void setProtocol(Protocol p) {
    protocol = p;
  }

  /** The protocol spoken to the device. */
  public Protocol getProtocol() {
    return protocol;
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
    scip11Connection = null;
    if (protocol == Protocol.SCIP_1_1) {
      handshake11(c);
      return;
    }
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

  private void handshake11(ArDeviceConnection c) throws IOException, InterruptedException {
    ScipBlock v = ask(c, Scip11.VERSION, "version");
    if (!Scip11.status(v).equals(Scip11.OK)) {
      throw new IOException(
          "the URG answered V with status '" + Scip11.status(v) + "': is it speaking SCIP 1.1?");
    }
    version = Scip11.info(v);
    UrgParams p = UrgParams.URG_04LX;
    params = p;
    setMaxRange(Math.min(p.maxRange(), Scip11.MAX_RANGE));
    if (c instanceof ArSerialConnection serial && settings.baud() != serial.getBaud()) {
      String s = Scip11.baudRequest(settings.baud());
      if (!Scip11.status(ask(c, s, "baud rate change")).equals(Scip11.OK)) {
        throw new IOException("the URG refused " + settings.baud() + " baud");
      }
      serial.setBaud(settings.baud());
    }
    firstStep = p.stepOf(settings.startDeg());
    lastStep = p.stepOf(settings.endDeg());
    String g = Scip11.distanceRequest(firstStep, lastStep, settings.clusterCount());
    scip11Request = g;
    ScipBlock first = ask(c, g, "distance reading");
    if (!Scip11.status(first).equals(Scip11.OK)) {
      throw new IOException("the URG refused " + g + " (status " + Scip11.status(first) + ")");
    }
    takeScan11(first);
    scip11Connection = c;
    request11(c);
  }

  private void request11(ArDeviceConnection c) {
    byte[] bytes = (scip11Request + "\n").getBytes(StandardCharsets.US_ASCII);
    lastRequestNanos = System.nanoTime();
    try {
      c.write(bytes, 0, bytes.length);
    } catch (IOException e) {
      // the reader notices the dead connection and reconnects; nothing to add here
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
    ArDeviceConnection c11 = scip11Connection;
    if (c11 != null && System.nanoTime() - lastRequestNanos > answerTimeoutMs * 1_000_000L) {
      request11(c11); // the answer was lost: ask again
    }
  }

  private void takeIfScan(ScipBlock b) {
    ArDeviceConnection c11 = scip11Connection;
    if (c11 != null) {
      if (b.echo().equals(scip11Request)) {
        if (Scip11.status(b).equals(Scip11.OK)) {
          takeScan11(b);
        }
        request11(c11);
      }
    } else if (b.echo().startsWith("MD") && b.status().equals("99")) {
      takeScan(b);
    }
  }

  private void takeScan11(ScipBlock b) {
    int[] raw;
    try {
      raw = Scip11.distances(b);
    } catch (IllegalArgumentException e) {
      getDropCounters().drop(DropReason.MALFORMED, e.getMessage());
      return;
    }
    publishRaw(raw);
  }

  private void takeScan(ScipBlock b) {
    int[] raw;
    try {
      // Line 2 is the time stamp; the distances follow.
      raw = Scip.decodeAll(b.joinedData(3), 3);
    } catch (IllegalArgumentException e) {
      getDropCounters().drop(DropReason.BAD_CHECKSUM, e.getMessage());
      return;
    }
    publishRaw(raw);
  }

  private void publishRaw(int[] raw) {
    UrgParams p = params;
    int cluster = settings.clusterCount();
    int expected = (lastStep - firstStep) / cluster + 1;
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
    if (scip11Connection != null) {
      scip11Connection = null; // SCIP 1.1 measures only when asked: stop asking
      return;
    }
    byte[] qt = "QT\n".getBytes(StandardCharsets.US_ASCII);
    c.write(qt, 0, qt.length);
  }
}
