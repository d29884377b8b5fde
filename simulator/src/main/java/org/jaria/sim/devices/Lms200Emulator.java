package org.jaria.sim.devices;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.connection.ArSerialConnection;
import org.jaria.laser.LmsCommands;
import org.jaria.laser.LmsReceiver;
import org.jaria.laser.LmsScanData;
import org.jaria.laser.LmsSettings;
import org.jaria.laser.LmsTelegram;
import org.jaria.protocol.DropCounters;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A SICK LMS-200 as seen from its serial port, measuring with a {@link LaserSensor}: it answers the
 * telegrams a driver sends (baud rate change, field of view, installation mode with its password,
 * configuration, continuous output on and off), each answer after an ACK byte, and while in
 * continuous mode sends one scan telegram per period. On a serial port a baud change really
 * switches the port after the answer, as the laser does.
 */
public final class Lms200Emulator extends EmulatedDevice {

  private static final Logger log = LoggerFactory.getLogger(Lms200Emulator.class);

  /** Status byte the laser appends to its answers: all well. */
  private static final int STATUS_OK = 0x10;

  private final LaserSensor sensor;
  private final LmsReceiver receiver = new LmsReceiver(false, new DropCounters("lms200-emulator"));
  private final List<LmsTelegram> requests = new ArrayList<>();
  private final long periodNanos;
  private int degrees = 180;
  private int incrementHundredths = 100;
  private int reflectorBits = 1;
  private String units = "1mm";
  private boolean installMode;
  private boolean streaming;
  private long nextScanAt;
  private final AtomicLong scansSent = new AtomicLong();
  private boolean zeroResolutionNoted;
  private final AtomicLong configurationsStored = new AtomicLong();
  private final List<Integer> modeChanges = new CopyOnWriteArrayList<>();
  private volatile long configureDelayMs;

  /**
   * An LMS-200 on {@code connection}.
   *
   * @param periodMs time between scans while streaming, ms (a real LMS-200 at 38400 baud manages
   *     about 5 scans a second of 181 readings)
   */
  public Lms200Emulator(
      ArDeviceConnection connection, LaserSensor sensor, DeviceFaults faults, long periodMs) {
    super(connection, faults, "lms200-emulator");
    this.sensor = sensor;
    this.periodNanos = TimeUnit.MILLISECONDS.toNanos(periodMs);
  }

  /** Starts an LMS-200 emulator on {@code connection}; close it to stop. */
  public static Lms200Emulator start(
      ArDeviceConnection connection, LaserSensor sensor, DeviceFaults faults, long periodMs)
      throws IOException {
    Lms200Emulator e = new Lms200Emulator(connection, sensor, faults, periodMs);
    e.start();
    return e;
  }

  @Override
  protected void received(byte[] b, int n) throws IOException, InterruptedException {
    receiver.feed(b, 0, n, requests::add);
    for (LmsTelegram t : List.copyOf(requests)) {
      handle(t);
    }
    requests.clear();
  }

  private void handle(LmsTelegram t) throws IOException, InterruptedException {
    switch (t.command()) {
      case LmsCommands.CHANGE_MODE -> changeMode(t);
      case LmsCommands.VARIANT -> variant(t);
      case LmsCommands.CONFIGURE -> configure(t);
      case LmsCommands.RESET -> {
        degrees = 180;
        incrementHundredths = 100;
        streaming = false;
        installMode = false;
        reply(0x91);
        reply(LmsCommands.POWER_ON);
      }
      case LmsCommands.STATUS -> reply(LmsCommands.STATUS_ANSWER, (byte) 0);
      default -> answer(new byte[] {LmsTelegram.NAK});
    }
  }

  private void changeMode(LmsTelegram t) throws IOException, InterruptedException {
    int mode = t.dataLength() > 0 ? t.u8(0) : -1;
    modeChanges.add(mode); // before the answer: a driver that has the answer finds it here
    switch (mode) {
      case 0x40, 0x41, 0x42 -> {
        reply(LmsCommands.MODE_ANSWER, (byte) 0);
        if (connection instanceof ArSerialConnection serial) {
          serial.setBaud(mode == 0x40 ? 38400 : mode == 0x41 ? 19200 : 9600);
        }
      }
      case LmsCommands.MODE_INSTALL -> {
        byte[] pw = Arrays.copyOfRange(t.data(), 1, t.dataLength());
        boolean ok = LmsCommands.PASSWORD.equals(new String(pw, StandardCharsets.US_ASCII));
        installMode = ok;
        reply(LmsCommands.MODE_ANSWER, (byte) (ok ? 0 : 1));
      }
      case LmsCommands.MODE_CONTINUOUS -> {
        installMode = false;
        reply(LmsCommands.MODE_ANSWER, (byte) 0);
        streaming = true;
        nextScanAt = connection.clock().nanoTime();
      }
      case LmsCommands.MODE_STOP -> {
        streaming = false;
        reply(LmsCommands.MODE_ANSWER, (byte) 0);
      }
      default -> reply(LmsCommands.MODE_ANSWER, (byte) 3);
    }
  }

  /**
   * The variant request (0x3B): scanning angle 180° or 100°, resolution 1°, 0.5° or (100° only)
   * 0.25°. A resolution of 0 keeps the current one and is answered as accepted: AriaCoda's {@code
   * ArLMS2xx} always asks for 0 (it reads an unset field instead of its increment choice), and its
   * users' lasers evidently carried on, so the emulator does too.
   */
  private void variant(LmsTelegram t) throws IOException, InterruptedException {
    boolean ok = t.dataLength() == 4;
    int w = ok ? t.u16(0) : 0;
    int inc = ok ? t.u16(2) : 0;
    if (inc == 0 && (w == 180 || w == 100)) {
      inc = w == 180 && incrementHundredths == 25 ? 100 : incrementHundredths;
      if (!zeroResolutionNoted) {
        zeroResolutionNoted = true;
        log.info(
            "variant request with resolution 0 (as AriaCoda's ArLMS2xx sends): keeping {}°",
            inc / 100.0);
      }
    }
    ok = ok && (w == 180 || w == 100) && (inc == 100 || inc == 50 || (inc == 25 && w == 100));
    if (ok) {
      degrees = w;
      incrementHundredths = inc;
    }
    reply(
        LmsCommands.VARIANT_ANSWER,
        (byte) (ok ? 1 : 0),
        (byte) degrees,
        (byte) (degrees >> 8),
        (byte) incrementHundredths,
        (byte) (incrementHundredths >> 8));
  }

  private void configure(LmsTelegram t) throws IOException, InterruptedException {
    if (!installMode || t.dataLength() < 7) {
      reply(LmsCommands.NOT_ACKNOWLEDGED);
      return;
    }
    if (configureDelayMs > 0) {
      // Storing the block in the EEPROM: the laser reads nothing meanwhile.
      connection.clock().sleepNanos(TimeUnit.MILLISECONDS.toNanos(configureDelayMs));
    }
    configurationsStored.incrementAndGet();
    reflectorBits = LmsSettings.reflectorBitsOfMode(t.u8(5));
    units = LmsSettings.unitsOfByte(t.u8(6));
    byte[] d = new byte[1 + t.dataLength()];
    d[0] = 1;
    System.arraycopy(t.data(), 0, d, 1, t.dataLength());
    reply(LmsCommands.CONFIGURE_ANSWER, d);
  }

  /** ACK, then the answer telegram with the status byte appended. */
  private void reply(int code, byte... data) throws IOException, InterruptedException {
    byte[] d = Arrays.copyOf(data, data.length + 1);
    d[data.length] = (byte) STATUS_OK;
    byte[] telegram = LmsTelegram.fromLaser(code, d).encode();
    byte[] out = new byte[1 + telegram.length];
    out[0] = LmsTelegram.ACK;
    System.arraycopy(telegram, 0, out, 1, telegram.length);
    answer(out);
  }

  @Override
  protected long millisToNextTick() {
    if (!streaming) {
      return 100;
    }
    return TimeUnit.NANOSECONDS.toMillis(nextScanAt - connection.clock().nanoTime());
  }

  @Override
  protected void tick() throws IOException {
    if (!streaming) {
      return;
    }
    nextScanAt += periodNanos;
    long now = connection.clock().nanoTime();
    if (nextScanAt < now) {
      nextScanAt = now + periodNanos; // fell behind: do not burst to catch up
    }
    byte[] bytes = scanTelegram().encode();
    if (faults.unplugAfterScans() >= 0 && scansSent.get() >= faults.unplugAfterScans()) {
      unplugMidway(bytes);
      return;
    }
    send(bytes, bytes.length);
    scansSent.incrementAndGet();
  }

  /** The scan telegram for what the sensor sees now. */
  private LmsTelegram scanTelegram() {
    double inc = incrementHundredths / 100.0;
    int count = (int) Math.round(degrees * 100.0 / incrementHundredths) + 1;
    double[] r = sensor.ranges(-degrees / 2.0, inc, count);
    int unit =
        switch (units) {
          case "1cm" -> 10;
          case "10cm" -> 100;
          default -> 1;
        };
    int mask = LmsScanData.distanceMask(reflectorBits);
    int[] raw = new int[count];
    for (int i = 0; i < count; i++) {
      raw[i] = r[i] >= sensor.maxRange() ? mask : (int) Math.min(mask, Math.round(r[i] / unit));
    }
    return LmsScanData.encode(raw, new int[count], unit, reflectorBits, STATUS_OK);
  }

  /** Scans sent so far (read from the device's thread, or after it ended). */
  public long getScansSent() {
    return scansSent.get();
  }

  /**
   * Makes the laser take {@code ms} (on the connection's clock) to store a configuration block
   * before it answers, as a real LMS-200 writing its EEPROM does (a slow unit takes over 10 s).
   */
  public void setConfigureDelayMs(long ms) {
    configureDelayMs = ms;
  }

  /** Configuration blocks stored so far: each one a write of the laser's EEPROM. */
  public long getConfigurationsStored() {
    return configurationsStored.get();
  }

  /**
   * The mode bytes of every mode change received, in order (0x42 is 9600 baud, 0x25 stop, ...),
   * each recorded before its answer is sent.
   */
  public List<Integer> getModeChanges() {
    return List.copyOf(modeChanges);
  }
}
