package org.jaria.robot;

import org.jaria.clock.Clock;
import org.jaria.geom.ArPose;
import org.jaria.geom.ArTransform;
import org.jaria.params.ArRobotParams;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.DropReason;
import org.jaria.protocol.packets.EncoderPacket;
import org.jaria.protocol.packets.IoPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.StandardSip;

/**
 * The stage after the router: the packet handlers for the standard SIP, the ENCODERpac and the
 * IOpac. A SIP goes through {@link SipProcessor} into a new {@link RobotStatus}, which this stage
 * publishes; the robot's getters read the latest. Handlers run on the cycle thread; the published
 * values are immutable and may be read from any thread.
 */
final class StatusStage {

  private final Clock clock;
  private final DropCounters drops;
  private final SipProcessor processor;
  private final StandardSip sip = new StandardSip();
  private volatile ArRobotParams params;
  private volatile EncoderPacket encoders = new EncoderPacket(0, 0);
  private volatile IoPacket io = new IoPacket(new int[0], new int[0], new int[0]);

  StatusStage(Clock clock, ArRobotParams params, DropCounters drops) {
    this.clock = clock;
    this.drops = drops;
    this.params = params;
    this.processor = new SipProcessor(params);
  }

  /** The parameters in use. */
  ArRobotParams params() {
    return params;
  }

  /** New parameters (once the robot is identified): sonar geometry and conversion factors. */
  void setParams(ArRobotParams p) {
    params = p;
    processor.setParams(p);
  }

  /** Forgets the odometry of an earlier connection. */
  void reset() {
    processor.reset();
  }

  /**
   * The latest status, with the encoder→global transform that made its pose. The processor
   * publishes it, so a relocalization racing a SIP cannot leave the older of the two published.
   */
  RobotStatus status() {
    return processor.last();
  }

  /** The latest ENCODERpac. */
  EncoderPacket encoders() {
    return encoders;
  }

  /** The latest IOpac. */
  IoPacket io() {
    return io;
  }

  /** Standard SIP handler: decodes it and publishes a new status. */
  boolean handleSip(ArRobotPacket p, long counter) {
    if (!PacketIds.isStandardSip(p.getID())) {
      return false;
    }
    if (!sip.decode(p)) {
      drops.drop(DropReason.MALFORMED, "short standard SIP");
      return true;
    }
    processor.process(sip, counter, clock.nanoTime());
    return true;
  }

  boolean handleEncoderPacket(ArRobotPacket p) {
    if (p.getID() != PacketIds.ENCODER) {
      return false;
    }
    EncoderPacket e = EncoderPacket.decode(p);
    if (e == null) {
      drops.drop(DropReason.MALFORMED, "short ENCODERpac");
    } else {
      encoders = e;
    }
    return true;
  }

  boolean handleIoPacket(ArRobotPacket p) {
    if (p.getID() != PacketIds.IO) {
      return false;
    }
    IoPacket q = IoPacket.decode(p);
    if (q == null) {
      drops.drop(DropReason.MALFORMED, "short IOpac");
    } else {
      io = q;
    }
    return true;
  }

  /** Declares the robot to be at {@code pose}; returns how the global frame moved. */
  ArTransform moveTo(ArPose pose) {
    return processor.moveTo(pose);
  }

  /** Maps odometry pose {@code encoder} to global pose {@code global}; returns the change. */
  ArTransform setEncoderTransform(ArPose encoder, ArPose global) {
    return processor.setEncoderTransform(encoder, global);
  }

  void setHeadingCorrection(HeadingCorrection c) {
    processor.setHeadingCorrection(c);
  }
}
