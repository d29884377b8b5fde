package org.jaria.robot;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArMath;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;
import org.jaria.params.ArRobotParams;
import org.jaria.protocol.packets.StandardSip;
import org.jaria.range.ArSensorReading;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Turns standard SIPs into {@link RobotStatus} snapshots: integrates the 15-bit wrapping position
 * counters into an odometry pose, applies the conversion factors, places sonar readings in global
 * coordinates, and keeps the encoder→global transform that localization uses to correct the pose.
 *
 * <p>SIPs are processed on the robot's cycle thread; {@link #moveTo} and {@link
 * #setEncoderTransform} may come from another thread (a localization task), so every method is
 * synchronized and every field is guarded by this object's monitor. The methods are short, and
 * contention is rare.
 */
final class SipProcessor {

  private static final Logger log = LoggerFactory.getLogger(SipProcessor.class);

  @GuardedBy("this")
  private ArRobotParams params;

  @GuardedBy("this")
  private final List<ArSensorReading> sonars = new ArrayList<>();

  @GuardedBy("this")
  private boolean first = true;

  @GuardedBy("this")
  private int lastX;

  @GuardedBy("this")
  private int lastY;

  @GuardedBy("this")
  private int lastTh;

  @GuardedBy("this")
  private ArPose rawEncoderPose = ArPose.ORIGIN;

  @GuardedBy("this")
  private ArPose encoderPose = ArPose.ORIGIN;

  @GuardedBy("this")
  private ArTransform encoderTransform = ArTransform.IDENTITY;

  @GuardedBy("this")
  private ArPose globalPose = ArPose.ORIGIN;

  @GuardedBy("this")
  private double odometerDistance;

  @GuardedBy("this")
  private double odometerDegrees;

  @GuardedBy("this")
  private HeadingCorrection headingCorrection;

  @GuardedBy("this")
  private boolean warnedExtraSonar;

  /**
   * The newest status. Written only while holding this object's monitor, so the last write is the
   * newest status even when a relocalization and a SIP race; read from any thread without it.
   */
  private volatile RobotStatus last;

  /** Reused for every SIP: every field is set each time. */
  @GuardedBy("this")
  private final RobotStatus.Builder builder = RobotStatus.builder();

  SipProcessor(ArRobotParams params) {
    setParams(params);
  }

  /** New parameters (after connecting): sonar geometry and conversion factors. */
  synchronized void setParams(ArRobotParams p) {
    this.params = p;
    sonars.clear();
    for (int i = 0; i < p.getNumSonar(); i++) {
      sonars.add(ArSensorReading.never(p.getSonarX(i), p.getSonarY(i), p.getSonarTh(i)));
    }
    last = RobotStatus.initial(sonars).toBuilder().encoderTransform(encoderTransform).build();
  }

  /** Forgets the odometry history (a new connection starts counting afresh). */
  synchronized void reset() {
    first = true;
    rawEncoderPose = ArPose.ORIGIN;
    encoderPose = ArPose.ORIGIN;
    odometerDistance = 0;
    odometerDegrees = 0;
    setParams(params);
  }

  synchronized void setHeadingCorrection(HeadingCorrection c) {
    headingCorrection = c;
  }

  /** Converts one SIP into a new status. */
  synchronized RobotStatus process(StandardSip sip, long counter, long nowNanos) {
    ArRobotParams p = params;
    int x = sip.getXPos();
    int y = sip.getYPos();
    int th = sip.getThPos();
    int qx;
    int qy;
    int qth;
    if (first) {
      qx = 0;
      qy = 0;
      qth = 0;
      first = false;
      rawEncoderPose =
          new ArPose(
              p.getDistConvFactor() * x,
              p.getDistConvFactor() * y,
              Math.toDegrees(p.getAngleConvFactor() * th));
      encoderPose = rawEncoderPose;
      encoderTransform = ArTransform.between(encoderPose, globalPose);
    } else {
      qx = wrap15(x - lastX);
      qy = wrap15(y - lastY);
      qth = wrapHeading(th - lastTh);
    }
    lastX = x;
    lastY = y;
    lastTh = th;

    double dx = p.getDistConvFactor() * qx;
    double dy = p.getDistConvFactor() * qy;
    double dth = Math.toDegrees(p.getAngleConvFactor() * qth);
    rawEncoderPose =
        new ArPose(rawEncoderPose.x() + dx, rawEncoderPose.y() + dy, rawEncoderPose.th() + dth);
    HeadingCorrection c = headingCorrection;
    // As in ARIA, the correction sees every SIP, the first one (with zero deltas) included.
    if (c != null) {
      dth = c.correctedDeltaTh(dx, dy, dth, nowNanos);
      // Rotate the position delta from the raw heading frame into the corrected one.
      double rot = Math.toRadians(ArMath.subAngle(encoderPose.th() + dth, rawEncoderPose.th()));
      double cos = Math.cos(rot);
      double sin = Math.sin(rot);
      double rdx = cos * dx - sin * dy;
      dy = sin * dx + cos * dy;
      dx = rdx;
    }
    encoderPose = new ArPose(encoderPose.x() + dx, encoderPose.y() + dy, encoderPose.th() + dth);
    globalPose = encoderTransform.doTransform(encoderPose);
    odometerDegrees += Math.abs(dth);
    odometerDistance += Math.hypot(dx, dy);

    double leftVel = p.getVelConvFactor() * sip.getLeftVel();
    double rightVel = p.getVelConvFactor() * sip.getRightVel();
    double battery = sip.getBattery() * 0.1;
    double control =
        ArMath.fixAngle(Math.toDegrees(p.getAngleConvFactor() * (sip.getControl() - th)));

    for (int i = 0; i < sip.getSonarCount(); i++) {
      int num = sip.getSonarNumber(i);
      int range = ArMath.roundInt(sip.getSonarRange(i) * p.getRangeConvFactor());
      if (num < sonars.size()) {
        // A later reading of the same sonar in this SIP replaces the earlier one.
        sonars.set(num, sonars.get(num).newData(range, globalPose, encoderPose, counter, nowNanos));
      } else if (!warnedExtraSonar) {
        warnedExtraSonar = true;
        log.warn(
            "robot sent a reading of sonar {} but its parameters define only {}: update the"
                + " parameter file or the firmware",
            num,
            sonars.size());
      }
    }

    int n = sip.getOptionalCount();
    double realBattery =
        sip.has(StandardSip.Optional.BATTERY_X10) ? sip.getBatteryX10() * 0.1 : battery;
    double rotVel =
        sip.has(StandardSip.Optional.ROT_VEL)
            ? sip.getRotVel() / 10.0
            : Math.toDegrees((rightVel - leftVel) / 2.0 * p.getDiffConvFactor());
    last =
        builder
            .counter(counter)
            .timeNanos(nowNanos)
            .pose(globalPose)
            .encoderPose(encoderPose)
            .rawEncoderPose(rawEncoderPose)
            .encoderTransform(encoderTransform)
            .vel((leftVel + rightVel) / 2.0)
            .rotVel(rotVel)
            .wheelVels(leftVel, rightVel)
            .batteryVoltage(battery)
            .realBatteryVoltage(realBattery)
            .stallValue(sip.getStallAndBumpers())
            .control(control)
            .flags(sip.getFlags())
            .compass(2 * sip.getCompass())
            .anPort(n > 1 ? sip.getAnPort() : 0)
            .analog(n > 2 ? sip.getAnalog() : 0)
            .digIn(n > 3 ? sip.getDigIn() : 0)
            .digOut(n > 4 ? sip.getDigOut() : 0)
            .gripState(n > 0 ? sip.getGripState() : 0)
            .chargeState(sip.has(StandardSip.Optional.CHARGE_STATE) ? sip.getChargeState() : -1)
            .faultFlags(sip.has(StandardSip.Optional.FAULT_FLAGS) ? sip.getFaultFlags() : 0)
            .moving(sip.isMoving())
            .odometer(odometerDistance, odometerDegrees)
            .sonars(sonars)
            .build();
    return last;
  }

  /**
   * A heading change in angle units (4096 per turn), folded into -2048..2047: the SIP reports
   * -180..+180 degrees, so crossing 180 would otherwise look like a whole turn the other way.
   */
  static int wrapHeading(int delta) {
    int d = Math.floorMod(delta + 2048, 4096) - 2048;
    return d;
  }

  /**
   * A difference of two 15-bit position counters (x, y), corrected for wrap-around: the SIP's
   * counters roll over at 32768, and no robot moves 4096 counts in one cycle.
   */
  static int wrap15(int delta) {
    if (delta > 0x1000) {
      return delta - 0x8000;
    }
    if (delta < -0x1000) {
      return delta + 0x8000;
    }
    return delta;
  }

  /**
   * Declares that the robot is now at {@code pose}: the encoder→global transform changes so the
   * current odometry maps there, and sonar readings move along. Returns how the global frame moved
   * (what range devices apply to their buffers); the new status carries the new transform.
   */
  synchronized ArTransform moveTo(ArPose pose) {
    ArTransform old = encoderTransform;
    encoderTransform = ArTransform.between(encoderPose, pose);
    ArTransform change = encoderTransform.compose(old.inverse());
    globalPose = encoderTransform.doTransform(encoderPose);
    for (int i = 0; i < sonars.size(); i++) {
      ArSensorReading r = sonars.get(i);
      if (r.range() >= 0) {
        sonars.set(i, r.applyTransform(change));
      }
    }
    last = last.relocalized(globalPose, encoderTransform, sonars);
    return change;
  }

  /**
   * Sets the transform so that odometry pose {@code encoder} corresponds to global pose {@code
   * global} (what a localizer computed for an earlier odometry reading). Returns how the global
   * frame moved.
   */
  synchronized ArTransform setEncoderTransform(ArPose encoder, ArPose global) {
    ArTransform target = ArTransform.between(encoder, global);
    return moveTo(target.doTransform(encoderPose));
  }

  /** The last status produced (any thread). */
  RobotStatus last() {
    return last;
  }
}
