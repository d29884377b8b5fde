package org.jaria.sim.serial;

/**
 * One auxiliary serial port of the simulated microcontroller, with the receive buffer ARCOS keeps
 * for it. Bytes written to the port (TTY2/3/4) go to the attached device; the device's answers wait
 * in the buffer until the client asks for them (GETAUX n):
 *
 * <ul>
 *   <li>with a device attached, a request for n bytes is answered once n bytes are buffered (ARIA's
 *       {@code ArVCC4} asks for an answer before it sends the command, and expects exactly the
 *       bytes it asked for);
 *   <li>with nothing attached, a request is answered at once with no bytes;
 *   <li>GETAUX 0 empties the buffer and cancels a waiting request.
 * </ul>
 *
 * <p>A full buffer drops its oldest bytes and counts them. Not thread-safe: the world thread uses
 * it.
 */
public final class AuxPort {

  /** Bytes the port buffers before it drops the oldest. */
  public static final int BUFFER_BYTES = 512;

  /** Most bytes one GETAUX can ask for (ARCOS: 1..200). */
  public static final int MAX_REQUEST = 200;

  private final int number;
  private final AuxSerialDevice device;
  private final byte[] ring = new byte[BUFFER_BYTES];
  private int head;
  private int size;
  private int requested;
  private long dropped;

  /** Port {@code number} (1..3) with {@code device} attached, or nothing if it is null. */
  public AuxPort(int number, AuxSerialDevice device) {
    if (number < 1 || number > 3) {
      throw new IllegalArgumentException("AUX port " + number + " not in 1..3");
    }
    this.number = number;
    this.device = device;
  }

  /** The port's number, 1..3. */
  public int number() {
    return number;
  }

  /** The attached device, or null. */
  public AuxSerialDevice device() {
    return device;
  }

  /** TTY2/TTY3/TTY4: the client sends {@code data} out of the port. */
  public void write(byte[] data) {
    if (device != null && data.length > 0) {
      device.receive(data, this::buffer);
    }
  }

  private void buffer(byte[] bytes) {
    for (byte b : bytes) {
      if (size == BUFFER_BYTES) {
        head = (head + 1) % BUFFER_BYTES;
        size--;
        dropped++;
      }
      ring[(head + size) % BUFFER_BYTES] = b;
      size++;
    }
  }

  /** GETAUX n: asks for {@code n} bytes (0 flushes the buffer and forgets a waiting request). */
  public void request(int n) {
    if (n <= 0) {
      head = 0;
      size = 0;
      requested = 0;
    } else {
      requested = Math.min(n, MAX_REQUEST);
    }
  }

  /**
   * The answer due to a waiting request, or null if none is due yet: the requested bytes once they
   * are buffered (they leave the buffer), or no bytes at once if nothing is attached.
   */
  public byte[] takeAnswer() {
    if (requested == 0) {
      return null;
    }
    if (device == null) {
      requested = 0;
      return new byte[0];
    }
    if (size < requested) {
      return null;
    }
    byte[] out = new byte[requested];
    for (int i = 0; i < out.length; i++) {
      out[i] = ring[head];
      head = (head + 1) % BUFFER_BYTES;
    }
    size -= out.length;
    requested = 0;
    return out;
  }

  /** Bytes waiting in the buffer. */
  public int buffered() {
    return size;
  }

  /** Bytes dropped because the buffer was full. */
  public long dropped() {
    return dropped;
  }
}
