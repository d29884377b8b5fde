package org.jaria.ptz;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.io.ByteArrayOutputStream;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.robot.ArRobot;

/**
 * The Sony EVI-D30/D70 pan-tilt-zoom camera (ARIA's {@code ArSonyPTZ}): ±95° pan, ±25° tilt, zoom
 * 0..1023, over VISCA.
 *
 * <p>Positions go out in the camera's units as Sony's technical manual gives them ({@code 0x370}
 * pan units are 100°, {@code 0x12C} tilt units 25°; an EVI-D70 in its D30 mode takes the same).
 * ARIA 2.9's driver scales pan by {@code 0x370} per 90° instead, so the same request points an ARIA
 * program's camera about 10% further than this one's.
 *
 * <p>Through the robot, the camera's acknowledges and completions are fetched and counted, and
 * {@link #requestPosition()} asks where the head is ({@link #getReportedPan()}).
 */
public class ArSonyPTZ extends ArPTZ {

  /** Largest pan, degrees. */
  public static final double MAX_PAN = 95;

  /** Largest tilt, degrees. */
  public static final double MAX_TILT = 25;

  /** Largest zoom. */
  public static final int MAX_ZOOM = 1023;

  /** Camera pan units per degree ({@code 0x370} = 100°). */
  public static final double DEG_TO_PAN = 0x370 / 100.0;

  /** Camera tilt units per degree ({@code 0x12C} = 25°). */
  public static final double DEG_TO_TILT = 0x12c / 25.0;

  private final Object parseLock = new Object();

  @GuardedBy("parseLock")
  private final ByteArrayOutputStream message = new ByteArrayOutputStream();

  private final AtomicLong acks = new AtomicLong();
  private final AtomicLong completions = new AtomicLong();
  private final AtomicLong errors = new AtomicLong();
  private volatile ViscaReply lastError;

  /** A camera on {@code robot}'s AUX1 port. */
  public ArSonyPTZ(ArRobot robot) {
    super(robot);
  }

  @Override
  public boolean init() {
    if (!send(Visca.init())) {
      return false;
    }
    expectReply(Visca.INIT_REPLY_BYTES);
    return panTilt(0, 0) && zoom(0);
  }

  @Override
  public String getTypeName() {
    return "sony";
  }

  @Override
  public double getMaxPan() {
    return MAX_PAN;
  }

  @Override
  public double getMaxTilt() {
    return MAX_TILT;
  }

  @Override
  public int getMaxZoom() {
    return MAX_ZOOM;
  }

  @Override
  protected boolean panTiltClamped(double panDeg, double tiltDeg) {
    return command(
        Visca.panTilt(
            (int) Math.round(panDeg * DEG_TO_PAN), (int) Math.round(tiltDeg * DEG_TO_TILT)));
  }

  @Override
  protected boolean zoomClamped(int value) {
    return command(Visca.zoom(value));
  }

  /** Back-lighting compensation on. */
  public boolean backLightingOn() {
    return command(Visca.backLight(true));
  }

  /** Back-lighting compensation off. */
  public boolean backLightingOff() {
    return command(Visca.backLight(false));
  }

  /** Asks for the pan-tilt and the zoom position. */
  @Override
  public boolean requestPosition() {
    if (!send(Visca.panTiltInquiry())) {
      return false;
    }
    expectReply(Visca.PAN_TILT_ANSWER_BYTES);
    if (!send(Visca.zoomInquiry())) {
      return false;
    }
    expectReply(Visca.ZOOM_ANSWER_BYTES);
    return true;
  }

  private boolean command(byte[] bytes) {
    if (!send(bytes)) {
      return false;
    }
    expectReply(Visca.COMMAND_REPLY_BYTES);
    return true;
  }

  @Override
  protected void replyBytes(byte[] data) {
    for (byte b : data) {
      byte[] whole = null;
      synchronized (parseLock) {
        message.write(b);
        if ((b & 0xFF) == 0xFF) {
          whole = message.toByteArray();
          message.reset();
        } else if (message.size() > 16) {
          message.reset(); // no VISCA message is this long: resynchronise on the next FF
        }
      }
      if (whole != null) {
        take(ViscaReply.of(whole));
      }
    }
  }

  private void take(ViscaReply r) {
    switch (r.kind()) {
      case ACK -> acks.incrementAndGet();
      case COMPLETION -> completions.incrementAndGet();
      case ERROR -> {
        errors.incrementAndGet();
        lastError = r;
      }
      case ANSWER -> {
        int n = r.length();
        if (n == Visca.PAN_TILT_ANSWER_BYTES) {
          setReportedPanTilt(r.value(0) / DEG_TO_PAN, r.value(1) / DEG_TO_TILT);
        } else if (n == Visca.ZOOM_ANSWER_BYTES) {
          setReportedZoom(r.value(0));
        }
      }
      default -> {
        // broadcasts coming back and unknown messages carry nothing to keep
      }
    }
  }

  /** Commands the camera acknowledged. */
  public long getAckCount() {
    return acks.get();
  }

  /** Commands the camera said it finished. */
  public long getCompletionCount() {
    return completions.get();
  }

  /** Error answers received. */
  public long getErrorCount() {
    return errors.get();
  }

  /** The last error answer, or null. */
  public ViscaReply getLastError() {
    return lastError;
  }
}
