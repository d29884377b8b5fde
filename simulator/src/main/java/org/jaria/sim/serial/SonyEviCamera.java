package org.jaria.sim.serial;

import java.io.ByteArrayOutputStream;
import java.util.function.Consumer;

/**
 * A Sony EVI-D30 pan/tilt/zoom camera (or an EVI-D70 in its D30/D31 mode) on an AUX port, speaking
 * VISCA as the camera does, so ARIA's {@code ArSonyPTZ} and JAria's run against it over the wire.
 *
 * <p>A VISCA message is a header byte ({@code 8x}: to camera x, {@code 88} broadcast), up to 14
 * bytes, and the terminator {@code FF}. Answers come from camera 1 (header {@code 90}):
 *
 * <ul>
 *   <li>a command ({@code 81 01 ...}): the acknowledge {@code 90 41 FF}, then the completion {@code
 *       90 51 FF};
 *   <li>an inquiry ({@code 81 09 ...}): one answer {@code 90 50 <data> FF}; pan-tilt position
 *       ({@code 06 12}) answers 8 nibbles (pan then tilt), zoom position ({@code 04 47}) 4 nibbles;
 *   <li>errors: {@code 90 60 02 FF} syntax error (an unknown or malformed message), {@code 90 61 41
 *       FF} not executable (a position outside the camera's range);
 *   <li>the broadcasts: interface clear {@code 88 01 00 01 FF} comes back unchanged, address set
 *       {@code 88 30 01 FF} comes back as {@code 88 30 02 FF} (the next free address after this one
 *       camera).
 * </ul>
 *
 * <p>Positions are the D30's units (Sony's technical manual): pan {@code FC90}..{@code 0370} is
 * −100°..+100° (positive to the right), tilt {@code FED4}..{@code 012C} is −25°..+25°, zoom {@code
 * 0000} (wide) .. {@code 03FF} (tele). The head reaches a commanded position at once, so the
 * completion follows the acknowledge directly. Not thread-safe: the world thread uses it.
 */
public final class SonyEviCamera implements AuxSerialDevice, PtzHead {

  /** Largest pan, units (100°). */
  public static final int MAX_PAN_UNITS = 0x370;

  /** Largest tilt, units (25°). */
  public static final int MAX_TILT_UNITS = 0x12C;

  /** Largest zoom position. */
  public static final int MAX_ZOOM = 0x3FF;

  /** Pan units per degree. */
  public static final double PAN_UNITS_PER_DEG = MAX_PAN_UNITS / 100.0;

  /** Tilt units per degree. */
  public static final double TILT_UNITS_PER_DEG = MAX_TILT_UNITS / 25.0;

  /** VISCA's longest message, terminator included. */
  private static final int MAX_MESSAGE = 16;

  private final ByteArrayOutputStream message = new ByteArrayOutputStream();
  private boolean powered = true;
  private boolean backLight;
  private int address;
  private int panUnits;
  private int tiltUnits;
  private int zoom;
  private long messages;
  private long skippedBytes;

  @Override
  public String name() {
    return "sony";
  }

  @Override
  public void receive(byte[] data, Consumer<byte[]> reply) {
    for (byte b : data) {
      int v = b & 0xFF;
      if (message.size() == 0 && (v & 0x80) == 0) {
        skippedBytes++; // not a header: line noise before a message
        continue;
      }
      message.write(v);
      if (v == 0xFF) {
        messages++;
        byte[] m = message.toByteArray();
        message.reset();
        answer(m, reply);
      } else if (message.size() >= MAX_MESSAGE) {
        skippedBytes += message.size();
        message.reset();
        reply.accept(bytes(0x90, 0x60, 0x03, 0xFF)); // message too long: buffer full
      }
    }
  }

  /** Executes one message (header .. FF) and hands the camera's answers to {@code reply}. */
  void answer(byte[] m, Consumer<byte[]> reply) {
    int header = m[0] & 0xFF;
    if (header == 0x88) {
      broadcast(m, reply);
      return;
    }
    if (header != 0x81 || m.length < 4) {
      reply.accept(syntaxError());
      return;
    }
    int kind = m[1] & 0xFF;
    if (kind == 0x09) {
      reply.accept(inquiry(m));
    } else if (kind == 0x01) {
      byte[] error = command(m);
      if (error != null) {
        reply.accept(error);
      } else {
        reply.accept(bytes(0x90, 0x41, 0xFF));
        reply.accept(bytes(0x90, 0x51, 0xFF));
      }
    } else {
      reply.accept(syntaxError());
    }
  }

  private void broadcast(byte[] m, Consumer<byte[]> reply) {
    if (m.length == 5 && m[1] == 0x01 && m[2] == 0x00 && m[3] == 0x01) {
      reply.accept(m.clone()); // interface clear goes round the chain and back
    } else if (m.length == 4 && m[1] == 0x30) {
      address = m[2] & 0x0F;
      reply.accept(bytes(0x88, 0x30, address + 1, 0xFF));
    } else {
      reply.accept(syntaxError());
    }
  }

  /** A command (81 01 ...): null if done, else the error answer. */
  private byte[] command(byte[] m) {
    int cat = m[2] & 0xFF;
    int op = m.length > 3 ? m[3] & 0xFF : -1;
    if (cat == 0x06 && (op == 0x02 || op == 0x03) && m.length == 15) {
      int pan = signedNibbles(m, 6);
      int tilt = signedNibbles(m, 10);
      int speedPan = m[4] & 0xFF;
      int speedTilt = m[5] & 0xFF;
      if (pan == Integer.MIN_VALUE || tilt == Integer.MIN_VALUE) {
        return syntaxError();
      }
      if (speedPan < 1 || speedPan > 0x18 || speedTilt < 1 || speedTilt > 0x14) {
        return syntaxError();
      }
      if (op == 0x03) {
        pan += panUnits;
        tilt += tiltUnits;
      }
      if (Math.abs(pan) > MAX_PAN_UNITS || Math.abs(tilt) > MAX_TILT_UNITS) {
        return notExecutable();
      }
      panUnits = pan;
      tiltUnits = tilt;
      return null;
    }
    if (cat == 0x06 && (op == 0x04 || op == 0x05) && m.length == 5) { // home, reset
      panUnits = 0;
      tiltUnits = 0;
      return null;
    }
    if (cat == 0x06 && op == 0x01 && m.length == 9) { // drive up/down/left/right/stop
      return null;
    }
    if (cat == 0x04 && op == 0x47 && m.length == 9) {
      int z = unsignedNibbles(m, 4);
      if (z < 0) {
        return syntaxError();
      }
      if (z > MAX_ZOOM) {
        return notExecutable();
      }
      zoom = z;
      return null;
    }
    if (cat == 0x04 && op == 0x07 && m.length == 6) { // zoom stop/tele/wide
      return null;
    }
    if (cat == 0x04 && (op == 0x33 || op == 0x00) && m.length == 6) {
      int arg = m[4] & 0xFF;
      if (arg != 0x02 && arg != 0x03) {
        return syntaxError();
      }
      if (op == 0x33) {
        backLight = arg == 0x02;
      } else {
        powered = arg == 0x02;
      }
      return null;
    }
    return syntaxError();
  }

  private byte[] inquiry(byte[] m) {
    int cat = m[2] & 0xFF;
    int op = m[3] & 0xFF;
    if (m.length != 5) {
      return syntaxError();
    }
    if (cat == 0x06 && op == 0x12) {
      byte[] a = new byte[11];
      a[0] = (byte) 0x90;
      a[1] = 0x50;
      putNibbles(a, 2, panUnits);
      putNibbles(a, 6, tiltUnits);
      a[10] = (byte) 0xFF;
      return a;
    }
    if (cat == 0x04 && op == 0x47) {
      byte[] a = new byte[7];
      a[0] = (byte) 0x90;
      a[1] = 0x50;
      putNibbles(a, 2, zoom);
      a[6] = (byte) 0xFF;
      return a;
    }
    if (cat == 0x04 && (op == 0x00 || op == 0x33)) {
      boolean on = op == 0x00 ? powered : backLight;
      return bytes(0x90, 0x50, on ? 0x02 : 0x03, 0xFF);
    }
    return syntaxError();
  }

  /** Four nibbles from {@code at} as a signed 16-bit value; MIN_VALUE if a byte is not a nibble. */
  private static int signedNibbles(byte[] m, int at) {
    int v = unsignedNibbles(m, at);
    return v < 0 ? Integer.MIN_VALUE : (short) v;
  }

  /** Four nibbles from {@code at} as 0..0xFFFF, or −1 if a byte is not a nibble. */
  private static int unsignedNibbles(byte[] m, int at) {
    int v = 0;
    for (int i = at; i < at + 4; i++) {
      int n = m[i] & 0xFF;
      if (n > 0x0F) {
        return -1;
      }
      v = (v << 4) | n;
    }
    return v;
  }

  private static void putNibbles(byte[] a, int at, int value) {
    int v = value & 0xFFFF;
    for (int i = 0; i < 4; i++) {
      a[at + i] = (byte) ((v >> (12 - 4 * i)) & 0x0F);
    }
  }

  private static byte[] syntaxError() {
    return bytes(0x90, 0x60, 0x02, 0xFF);
  }

  private static byte[] notExecutable() {
    return bytes(0x90, 0x61, 0x41, 0xFF);
  }

  private static byte[] bytes(int... v) {
    byte[] b = new byte[v.length];
    for (int i = 0; i < v.length; i++) {
      b[i] = (byte) v[i];
    }
    return b;
  }

  @Override
  public Pointing pointing() {
    return new Pointing(getPan(), getTilt(), zoom / (double) MAX_ZOOM);
  }

  /** Pan, degrees, positive to the right. */
  public double getPan() {
    return panUnits / PAN_UNITS_PER_DEG;
  }

  /** Tilt, degrees, positive up. */
  public double getTilt() {
    return tiltUnits / TILT_UNITS_PER_DEG;
  }

  /** Pan, camera units. */
  public int getPanUnits() {
    return panUnits;
  }

  /** Tilt, camera units. */
  public int getTiltUnits() {
    return tiltUnits;
  }

  /** Zoom position, 0..{@value #MAX_ZOOM}. */
  public int getZoom() {
    return zoom;
  }

  /** Whether back-light compensation is on. */
  public boolean isBackLight() {
    return backLight;
  }

  /** Whether the camera is powered. */
  public boolean isPowered() {
    return powered;
  }

  /** The address the last address-set broadcast gave this camera (0 before one). */
  public int getAddress() {
    return address;
  }

  /** Complete messages received. */
  public long messages() {
    return messages;
  }

  /** Bytes skipped as not part of a message. */
  public long skippedBytes() {
    return skippedBytes;
  }
}
