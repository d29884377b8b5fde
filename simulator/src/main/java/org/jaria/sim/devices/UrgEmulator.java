package org.jaria.sim.devices;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.connection.ArSerialConnection;
import org.jaria.laser.Scip;
import org.jaria.laser.Scip11;
import org.jaria.laser.UrgParams;

/**
 * A Hokuyo URG-04LX as seen from its serial (or USB) port, measuring with a {@link LaserSensor}: it
 * answers the SCIP 2.0 requests a driver sends (SCIP2.0, VV, PP, BM, QT, RS, SS, GD/GS and MD/MS)
 * and, while an MD/MS request is running, sends one scan per period.
 *
 * <p>Started with {@link #startScip11}, it begins in SCIP 1.1, as a URG-04LX from the factory does:
 * V (version), S (serial rate), G (one scan, 2-character distances), L (laser on/off), each
 * answered by its echo, a one-character status ({@code 0} done, {@code 1} a bad parameter, {@code
 * E} an unknown command) and an empty line; {@code SCIP2.0} switches it to SCIP 2.0.
 */
public final class UrgEmulator extends EmulatedDevice {

  private final LaserSensor sensor;
  private final UrgParams params = UrgParams.URG_04LX;
  private final long periodNanos;
  private final StringBuilder line = new StringBuilder();
  private final AtomicLong scansSent = new AtomicLong();
  private final long startNanos;
  private boolean laserOn;
  private String streamCommand;
  private int streamScansLeft;
  private long nextScanAt;
  private boolean scip11;

  /**
   * A URG on {@code connection}.
   *
   * @param periodMs time between scans while measuring continuously (a URG-04LX: 100 ms)
   */
  public UrgEmulator(
      ArDeviceConnection connection, LaserSensor sensor, DeviceFaults faults, long periodMs) {
    super(connection, faults, "urg-emulator");
    this.sensor = sensor;
    this.periodNanos = TimeUnit.MILLISECONDS.toNanos(periodMs);
    this.startNanos = connection.clock().nanoTime();
  }

  /** Starts a URG emulator on {@code connection}; close it to stop. */
  public static UrgEmulator start(
      ArDeviceConnection connection, LaserSensor sensor, DeviceFaults faults, long periodMs)
      throws IOException {
    UrgEmulator e = new UrgEmulator(connection, sensor, faults, periodMs);
    e.start();
    return e;
  }

  /** Starts a URG emulator that speaks SCIP 1.1 until told {@code SCIP2.0}; close it to stop. */
  public static UrgEmulator startScip11(
      ArDeviceConnection connection, LaserSensor sensor, DeviceFaults faults, long periodMs)
      throws IOException {
    UrgEmulator e = new UrgEmulator(connection, sensor, faults, periodMs);
    e.scip11 = true;
    e.start();
    return e;
  }

  @Override
  protected void received(byte[] b, int n) throws IOException, InterruptedException {
    for (int i = 0; i < n; i++) {
      char c = (char) (b[i] & 0xff);
      if (c == '\n' || c == '\r') {
        if (line.length() > 0) {
          String cmd = line.toString();
          line.setLength(0);
          handle(cmd);
        }
      } else if (line.length() < 64) {
        line.append(c);
      }
    }
  }

  private void handle(String cmd) throws IOException, InterruptedException {
    if (scip11) {
      handle11(cmd);
    } else if (cmd.equals("SCIP2.0")) {
      reply(cmd, "0E"); // already in SCIP 2.0
    } else if (cmd.startsWith("VV")) {
      reply(
          cmd,
          "00",
          Scip.infoLine("VEND", "Hokuyo Automatic Co.,Ltd."),
          Scip.infoLine("PROD", "SOKUIKI Sensor URG-04LX"),
          Scip.infoLine("FIRM", "3.3.00,06/10/13(JAria emulator)"),
          Scip.infoLine("PROT", "SCIP 2.0"),
          Scip.infoLine("SERI", "H0000000"));
    } else if (cmd.startsWith("PP")) {
      reply(cmd, "00", params.infoLines());
    } else if (cmd.startsWith("BM")) {
      reply(cmd, laserOn ? "02" : "00");
      laserOn = true;
    } else if (cmd.startsWith("QT") || cmd.startsWith("RS")) {
      laserOn = false;
      streamCommand = null;
      reply(cmd, "00");
    } else if (cmd.startsWith("SS") && cmd.length() == 8) {
      setBaud(cmd);
    } else if ((cmd.startsWith("GD") || cmd.startsWith("GS")) && cmd.length() == 12) {
      single(cmd);
    } else if ((cmd.startsWith("MD") || cmd.startsWith("MS")) && cmd.length() == 15) {
      startStream(cmd);
    } else {
      reply(cmd, "0E");
    }
  }

  private void handle11(String cmd) throws IOException, InterruptedException {
    if (cmd.equals("SCIP2.0")) {
      scip11 = false;
      reply11(cmd, "0");
    } else if (cmd.equals("V")) {
      reply11(
          cmd,
          "0",
          "VEND:Hokuyo Automatic Co.,Ltd.",
          "PROD:SOKUIKI Sensor URG-04LX",
          "FIRM:3.3.00,06/10/13(JAria emulator)",
          "PROT:SCIP 1.1",
          "SERI:H0000000",
          "STAT:sensor is working normally");
    } else if (cmd.startsWith("S") && cmd.length() == 14) {
      int baud;
      try {
        baud = Integer.parseInt(cmd.substring(1, 7));
      } catch (NumberFormatException e) {
        baud = -1;
      }
      if (baud != 19200 && baud != 38400 && baud != 57600 && baud != 115200) {
        reply11(cmd, "1");
        return;
      }
      reply11(cmd, "0");
      if (connection instanceof ArSerialConnection serial) {
        serial.setBaud(baud);
      }
    } else if (cmd.startsWith("G") && cmd.length() == 9) {
      int[] r;
      try {
        r =
            new int[] {
              Integer.parseInt(cmd.substring(1, 4)),
              Integer.parseInt(cmd.substring(4, 7)),
              Math.max(1, Integer.parseInt(cmd.substring(7, 9)))
            };
      } catch (NumberFormatException e) {
        reply11(cmd, "1");
        return;
      }
      if (!validRange(r)) {
        reply11(cmd, "1");
        return;
      }
      reply11(cmd, "0", Scip11.dataLines(encoded(r, 2)).toArray(String[]::new));
    } else if (cmd.equals("L1") || cmd.equals("L0")) {
      laserOn = cmd.equals("L1");
      reply11(cmd, "0");
    } else {
      reply11(cmd, "E");
    }
  }

  private void reply11(String echo, String status, String... lines)
      throws IOException, InterruptedException {
    StringBuilder sb = new StringBuilder();
    sb.append(echo).append('\n').append(status).append('\n');
    for (String l : lines) {
      sb.append(l).append('\n');
    }
    sb.append('\n');
    answer(sb.toString().getBytes(StandardCharsets.US_ASCII));
  }

  private void setBaud(String cmd) throws IOException, InterruptedException {
    int baud;
    try {
      baud = Integer.parseInt(cmd.substring(2));
    } catch (NumberFormatException e) {
      reply(cmd, "01");
      return;
    }
    if (baud != 19200 && baud != 38400 && baud != 57600 && baud != 115200) {
      reply(cmd, "02");
      return;
    }
    reply(cmd, "00");
    if (connection instanceof ArSerialConnection serial) {
      serial.setBaud(baud);
    }
  }

  private int[] range(String cmd) {
    int first = Integer.parseInt(cmd.substring(2, 6));
    int last = Integer.parseInt(cmd.substring(6, 10));
    int cluster = Integer.parseInt(cmd.substring(10, 12));
    return new int[] {first, last, Math.max(1, cluster)};
  }

  private void single(String cmd) throws IOException, InterruptedException {
    int[] r;
    try {
      r = range(cmd);
    } catch (NumberFormatException e) {
      reply(cmd, "02");
      return;
    }
    if (!laserOn) {
      reply(cmd, "10");
      return;
    }
    if (!validRange(r)) {
      reply(cmd, "04");
      return;
    }
    List<String> lines = scanLines(r, cmd.startsWith("GD") ? 3 : 2);
    reply(cmd, "00", lines.toArray(String[]::new));
  }

  private boolean validRange(int[] r) {
    return r[0] >= params.firstStep() && r[1] <= params.lastStep() && r[0] <= r[1];
  }

  private void startStream(String cmd) throws IOException, InterruptedException {
    int[] r;
    int scans;
    try {
      r = range(cmd);
      scans = Integer.parseInt(cmd.substring(13, 15));
    } catch (NumberFormatException e) {
      reply(cmd, "02");
      return;
    }
    if (!validRange(r)) {
      reply(cmd, "04");
      return;
    }
    reply(cmd, "00");
    laserOn = true;
    streamCommand = cmd;
    streamScansLeft = scans == 0 ? -1 : scans;
    nextScanAt = connection.clock().nanoTime();
  }

  /** Time stamp line, then the distance lines. */
  private List<String> scanLines(int[] r, int chars) {
    long ms = TimeUnit.NANOSECONDS.toMillis(connection.clock().nanoTime() - startNanos);
    String stamp = Scip.encode((int) (ms & 0xffffff), 4);
    List<String> lines = new ArrayList<>();
    lines.add(stamp + Scip.checksum(stamp));
    lines.addAll(Scip.dataLines(encoded(r, chars)));
    return lines;
  }

  /** The distances of steps {@code r} encoded in {@code chars} characters each. */
  private String encoded(int[] r, int chars) {
    int count = (r[1] - r[0]) / r[2] + 1;
    double firstDeg = params.angleOf(r[0] + (r[2] - 1) / 2.0);
    double inc = r[2] * 360.0 / params.stepsPerTurn();
    double[] d = sensor.ranges(firstDeg, inc, count);
    StringBuilder enc = new StringBuilder(count * chars);
    int cap = (1 << (6 * chars)) - 1;
    for (double v : d) {
      // Beyond the maximum range the URG reports an error code (below DMIN): 0 here.
      int mm = v >= Math.min(sensor.maxRange(), params.maxRange()) ? 0 : (int) Math.round(v);
      // two characters carry at most 4095: a farther echo reads as "no echo" (0), as in 1.1
      enc.append(Scip.encode(mm > cap ? 0 : mm, chars));
    }
    return enc.toString();
  }

  private void reply(String echo, String status, String... lines)
      throws IOException, InterruptedException {
    answer(block(echo, status, lines));
  }

  private static byte[] block(String echo, String status, String... lines) {
    StringBuilder sb = new StringBuilder();
    sb.append(echo).append('\n').append(Scip.statusLine(status)).append('\n');
    for (String l : lines) {
      sb.append(l).append('\n');
    }
    sb.append('\n');
    return sb.toString().getBytes(StandardCharsets.US_ASCII);
  }

  @Override
  protected long millisToNextTick() {
    if (streamCommand == null) {
      return 100;
    }
    return TimeUnit.NANOSECONDS.toMillis(nextScanAt - connection.clock().nanoTime());
  }

  @Override
  protected void tick() throws IOException {
    String cmd = streamCommand;
    if (cmd == null) {
      return;
    }
    nextScanAt += periodNanos;
    long now = connection.clock().nanoTime();
    if (nextScanAt < now) {
      nextScanAt = now + periodNanos;
    }
    int[] r = range(cmd);
    String echo =
        cmd.substring(0, 13) + String.format(Locale.ROOT, "%02d", Math.max(0, streamScansLeft - 1));
    if (streamScansLeft < 0) {
      echo = cmd;
    }
    byte[] bytes =
        block(echo, "99", scanLines(r, cmd.startsWith("MD") ? 3 : 2).toArray(String[]::new));
    if (faults.unplugAfterScans() >= 0 && scansSent.get() >= faults.unplugAfterScans()) {
      unplugMidway(bytes);
      return;
    }
    send(bytes, bytes.length);
    scansSent.incrementAndGet();
    if (streamScansLeft > 0 && --streamScansLeft == 0) {
      streamCommand = null;
    }
  }

  /** Scans sent so far by continuous measurement. */
  public long getScansSent() {
    return scansSent.get();
  }
}
