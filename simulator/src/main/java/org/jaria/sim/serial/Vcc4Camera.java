package org.jaria.sim.serial;

import java.io.ByteArrayOutputStream;
import java.util.function.Consumer;

/**
 * A Canon VC-C4 pan/tilt/zoom camera on an AUX port, answering as the real camera does so that
 * ARIA's {@code ArVCC4} runs bidirectionally.
 *
 * <p>Commands arrive as frames {@code FF 30 30 00 <command> <parameters> EF}; bytes before a {@code
 * FF} are line noise and are skipped. Every frame gets an answer that starts {@code FE 30 30} and
 * ends {@code EF}:
 *
 * <ul>
 *   <li>a plain command: 6 bytes {@code FE 30 30 <code> 30 EF}, where the code is {@code 30} done,
 *       {@code 35} bad parameter, {@code 39} not in host control mode (send {@code 90 30} first);
 *   <li>the pan/tilt position request {@code 63}: 14 bytes {@code FE 30 30 30 30 <pan> <tilt> EF},
 *       each position four upper-case hex digits in 0.1125° units offset by {@code 8000};
 *   <li>the zoom position request {@code B4 30}: 10 bytes {@code FE 30 30 30 30 <zoom> EF}.
 * </ul>
 *
 * <p>The head reaches a commanded position at once (a client polling the position sees the target
 * on its next request). Not thread-safe: the world thread uses it.
 */
public final class Vcc4Camera implements AuxSerialDevice, PtzHead {

  /** Degrees per pan/tilt unit. */
  public static final double DEGREES_PER_UNIT = 0.1125;

  /** Answer code: done. */
  public static final int OK = 0x30;

  /** Answer code: a parameter is out of range or not hexadecimal. */
  public static final int PARAM_ERROR = 0x35;

  /** Answer code: the camera is not in host control mode. */
  public static final int MODE_ERROR = 0x39;

  /** Largest pan magnitude, units (about 98°). */
  public static final int MAX_PAN_UNITS = 875;

  /** Tilt range limits the camera accepts, units (about −30°..+90°). */
  public static final int MIN_TILT_UNITS = -267;

  /** Upper tilt limit the camera accepts, units. */
  public static final int MAX_TILT_UNITS = 800;

  /** Largest optical zoom position. */
  public static final int MAX_ZOOM = 1960;

  private static final int MAX_FRAME = 32;

  private final ByteArrayOutputStream frame = new ByteArrayOutputStream();
  private boolean inFrame;
  private boolean powered;
  private boolean hostMode;
  private int panUnits;
  private int tiltUnits;
  private int zoom;
  private int tiltMin = -267;
  private int tiltMax = 267;
  private int panSlew;
  private int tiltSlew;
  private long frames;
  private long skippedBytes;

  @Override
  public String name() {
    return "vcc4";
  }

  @Override
  public void receive(byte[] data, Consumer<byte[]> reply) {
    for (byte b : data) {
      int v = b & 0xFF;
      if (v == 0xFF) {
        if (inFrame) {
          skippedBytes += frame.size(); // an unfinished frame: the camera drops it
        }
        frame.reset();
        inFrame = true;
        frame.write(v);
      } else if (!inFrame) {
        skippedBytes++;
      } else {
        frame.write(v);
        if (v == 0xEF) {
          inFrame = false;
          frames++;
          reply.accept(answer(frame.toByteArray()));
        } else if (frame.size() > MAX_FRAME) {
          skippedBytes += frame.size();
          frame.reset();
          inFrame = false;
        }
      }
    }
  }

  /**
   * Executes one complete frame ({@code FF 30 30 00 cmd ... EF}) and returns the camera's answer.
   */
  byte[] answer(byte[] f) {
    if (f.length < 6 || f[1] != 0x30 || f[2] != 0x30) {
      return status(PARAM_ERROR);
    }
    int cmd = f[4] & 0xFF;
    int nParams = f.length - 6;
    int p0 = nParams > 0 ? f[5] & 0xFF : -1;
    switch (cmd) {
      case 0xA0 -> { // power: 31 on, 30 off
        powered = p0 == 0x31;
        return status(OK);
      }
      case 0x90 -> { // 30 host control mode, 31 local
        hostMode = p0 == 0x30;
        return status(OK);
      }
      default -> {}
    }
    if (!powered || !hostMode) {
      return status(MODE_ERROR);
    }
    return switch (cmd) {
      case 0x58 -> { // pedestal initialise: home
        panUnits = 0;
        tiltUnits = 0;
        yield status(OK);
      }
      case 0x53, 0xA2, 0x8E, 0xB7, 0xA1, 0xB0, 0x76, 0xB5, 0xA5 -> status(OK);
      case 0x50 -> {
        int v = hex(f, 5, 3);
        panSlew = v;
        yield status(v < 8 || v > 800 ? PARAM_ERROR : OK);
      }
      case 0x51 -> {
        int v = hex(f, 5, 3);
        tiltSlew = v;
        yield status(v < 8 || v > 662 ? PARAM_ERROR : OK);
      }
      case 0x62 -> panTilt(f, nParams);
      case 0x64 -> setRange(f, nParams, p0);
      case 0x63 -> position(hexOf(panUnits + 0x8000), hexOf(tiltUnits + 0x8000));
      case 0xB3 -> {
        int z = nParams == 4 ? hex(f, 5, 4) : -1;
        if (z < 0 || z > MAX_ZOOM) {
          yield status(PARAM_ERROR);
        }
        zoom = z;
        yield status(OK);
      }
      case 0xB4 -> position(hexOf(zoom));
      default -> status(PARAM_ERROR);
    };
  }

  private byte[] panTilt(byte[] f, int nParams) {
    if (nParams != 8) {
      return status(PARAM_ERROR);
    }
    int pan = hex(f, 5, 4);
    int tilt = hex(f, 9, 4);
    if (pan < 0 || tilt < 0) {
      return status(PARAM_ERROR);
    }
    pan -= 0x8000;
    tilt -= 0x8000;
    if (Math.abs(pan) > MAX_PAN_UNITS || tilt < tiltMin || tilt > tiltMax) {
      return status(PARAM_ERROR);
    }
    panUnits = pan;
    tiltUnits = tilt;
    return status(OK);
  }

  /** 64 31 min max: the tilt range (64 30: the pan range, accepted and kept at the maximum). */
  private byte[] setRange(byte[] f, int nParams, int which) {
    if (nParams != 9) {
      return status(PARAM_ERROR);
    }
    int lo = hex(f, 6, 4);
    int hi = hex(f, 10, 4);
    if (lo < 0 || hi < 0) {
      return status(PARAM_ERROR);
    }
    lo -= 0x8000;
    hi -= 0x8000;
    if (which == 0x31) {
      if (lo > hi || lo < MIN_TILT_UNITS || hi > MAX_TILT_UNITS) {
        return status(PARAM_ERROR);
      }
      tiltMin = lo;
      tiltMax = hi;
    }
    return status(OK);
  }

  private static byte[] status(int code) {
    return new byte[] {(byte) 0xFE, 0x30, 0x30, (byte) code, 0x30, (byte) 0xEF};
  }

  /** A data answer: FE 30 30 30 30, the hex groups, EF. */
  private static byte[] position(byte[]... groups) {
    ByteArrayOutputStream out = new ByteArrayOutputStream();
    out.writeBytes(new byte[] {(byte) 0xFE, 0x30, 0x30, 0x30, 0x30});
    for (byte[] g : groups) {
      out.writeBytes(g);
    }
    out.write(0xEF);
    return out.toByteArray();
  }

  /** Four upper-case hex digits. */
  private static byte[] hexOf(int v) {
    String s = String.format("%04X", v & 0xFFFF);
    return s.getBytes(java.nio.charset.StandardCharsets.US_ASCII);
  }

  /** {@code n} ASCII hex digits of {@code f} from {@code off}, or −1 if any is not hex. */
  private static int hex(byte[] f, int off, int n) {
    if (off + n > f.length - 1) {
      return -1;
    }
    int v = 0;
    for (int i = off; i < off + n; i++) {
      int d = Character.digit(f[i] & 0xFF, 16);
      if (d < 0) {
        return -1;
      }
      v = v * 16 + d;
    }
    return v;
  }

  /**
   * {@inheritDoc} The camera's pan units are positive to the right (Canon's manual: "pan right 90
   * degrees" is {@code +800} units), as ARIA's {@code ArPTZ} pans, so {@link #getPan()} is the
   * head's pan to the right.
   */
  @Override
  public Pointing pointing() {
    return new Pointing(getPan(), getTilt(), zoom / (double) MAX_ZOOM);
  }

  /** Pan, degrees, positive to the right (the sign on the wire). */
  public double getPan() {
    return panUnits * DEGREES_PER_UNIT;
  }

  /** Tilt, degrees (positive up). */
  public double getTilt() {
    return tiltUnits * DEGREES_PER_UNIT;
  }

  /** Optical zoom position, 0..{@value #MAX_ZOOM}. */
  public int getZoom() {
    return zoom;
  }

  /** Whether the camera is powered. */
  public boolean isPowered() {
    return powered;
  }

  /** Whether the camera takes commands from the host (after {@code 90 30}). */
  public boolean isHostMode() {
    return hostMode;
  }

  /** Pan speed, units per second (as last set). */
  public int getPanSlewUnits() {
    return panSlew;
  }

  /** Tilt speed, units per second (as last set). */
  public int getTiltSlewUnits() {
    return tiltSlew;
  }

  /** Complete frames received. */
  public long frames() {
    return frames;
  }

  /** Bytes skipped as not part of a frame. */
  public long skippedBytes() {
    return skippedBytes;
  }
}
