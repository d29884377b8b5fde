package org.jaria.sim;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import org.jaria.connection.ArDeviceConnection;
import org.jaria.connection.PipeConnection;
import org.jaria.geom.ArPose;
import org.jaria.protocol.DropCounters;
import org.jaria.sim.camera.CameraMount;
import org.jaria.sim.robot.RobotBody;
import org.jaria.sim.robot.RobotModel;
import org.jaria.sim.serial.AuxSerialDevice;
import org.jaria.sim.serial.PtzHead;
import org.jaria.sim.server.ArcosSession;
import org.jaria.sim.server.ClientKind;

/**
 * A robot in a {@link SimWorld}, seen from a test or a tool: connect a client to it, read and set
 * its true pose, read what its sensors really saw. Every method is thread-safe (it takes the
 * world's lock).
 */
public final class SimRobot implements CameraMount {

  private final SimWorld world;
  private final RobotSlot slot;

  SimRobot(SimWorld world, RobotSlot slot) {
    this.world = world;
    this.slot = slot;
  }

  /** The robot's name. */
  public String getName() {
    return slot.body.name();
  }

  /**
   * The robot's number in its world: 0 for the first robot added, 1 for the next, and so on. A
   * number is never given to another robot, even after this one was removed.
   */
  @Override
  public int getIndex() {
    return slot.body.index();
  }

  /** The robot's model. */
  public RobotModel getModel() {
    return slot.body.model();
  }

  /** The world it lives in (or lived in, once removed). */
  public SimWorld getWorld() {
    return world;
  }

  /** The robot factory that made it for its client, or null for a robot with its own port. */
  public RobotFactory getFactory() {
    return slot.factory;
  }

  /**
   * Whether it was taken out of its world ({@link SimWorld#removeRobot}, or its client left a robot
   * factory's robot).
   */
  public boolean isRemoved() {
    world.lock.lock();
    try {
      return slot.removed;
    } finally {
      world.lock.unlock();
    }
  }

  /**
   * Connects an in-process client: returns the client's end of a new in-memory connection (open, on
   * the world's clock) whose other end the world serves like a TCP client. A client connected
   * before is dropped.
   *
   * @throws IllegalStateException if the world is closed or the robot was removed from it
   */
  public ArDeviceConnection connectInMemory() {
    world.lock.lock();
    try {
      world.requireOpen();
      if (slot.removed) {
        throw new IllegalStateException(
            "robot " + getName() + " was removed from its world; connect to a robot that is in it");
      }
      slot.endSession("replaced by a new in-memory connection");
      PipeConnection.Pair pair = PipeConnection.pair(world.getClock(), "sim-" + getName());
      try {
        pair.a().open();
        pair.b().open();
      } catch (IOException e) {
        throw new UncheckedIOException(e);
      }
      slot.clients.attach(pair.b(), ClientKind.IN_MEMORY);
      return pair.a();
    } finally {
      world.lock.unlock();
    }
  }

  /**
   * Drops the client as if its cable were pulled: the client's reads see the end of the stream, the
   * robot stops. Does nothing without a client.
   */
  public void dropConnection() {
    world.lock.lock();
    try {
      for (ArcosSession s : slot.clients.all()) {
        if (s.connection() instanceof PipeConnection p) {
          p.breakConnection();
        }
      }
      slot.endSession("dropped through the simulator API");
    } finally {
      world.lock.unlock();
    }
  }

  /** Whether a client is connected (holding the robot or still in its handshake). */
  public boolean isClientConnected() {
    world.lock.lock();
    try {
      return slot.clients.hasConnections();
    } finally {
      world.lock.unlock();
    }
  }

  /** Whether a client has opened the robot (SIPs are flowing). */
  public boolean isSessionOpen() {
    world.lock.lock();
    try {
      ArcosSession s = slot.session();
      return s != null && s.state() == ArcosSession.State.OPEN;
    } finally {
      world.lock.unlock();
    }
  }

  /** Client connections this robot has had so far. */
  public long getSessionCount() {
    world.lock.lock();
    try {
      return slot.clients.connections();
    } finally {
      world.lock.unlock();
    }
  }

  /** The TCP port the robot listens on, or -1 before {@link SimWorld#listen()}. */
  public int getPort() {
    world.lock.lock();
    try {
      return slot.boundPort;
    } finally {
      world.lock.unlock();
    }
  }

  /** Packets from clients dropped as garbage, truncated or corrupt, over all sessions. */
  public DropCounters getDropCounters() {
    return slot.drops;
  }

  /** Where the robot really is. */
  @Override
  public ArPose getTruePose() {
    world.lock.lock();
    try {
      return slot.body.getTruePose();
    } finally {
      world.lock.unlock();
    }
  }

  /** Where the robot started (and where SIM_RESET takes it back to). */
  public ArPose getStartPose() {
    world.lock.lock();
    try {
      return slot.body.getStartPose();
    } finally {
      world.lock.unlock();
    }
  }

  /**
   * How far the robot has driven since it was made, mm: the length of its true path, forwards and
   * backwards alike (an odometer), not the distance from where it started.
   */
  public double getDistanceDriven() {
    world.lock.lock();
    try {
      return slot.body.travelled();
    } finally {
      world.lock.unlock();
    }
  }

  /** Moves the robot (its odometry does not notice, as with SIM_SET_POSE). */
  public void setTruePose(ArPose p) {
    world.lock.lock();
    try {
      slot.body.setTruePose(p);
      world.geometry().robotsMoved();
    } finally {
      world.lock.unlock();
    }
  }

  /** Where the robot's odometry says it is (the SIP's position). */
  public ArPose getOdometryPose() {
    world.lock.lock();
    try {
      return slot.body.getOdometryPose();
    } finally {
      world.lock.unlock();
    }
  }

  /** Translational velocity, mm/s. */
  public double getVel() {
    world.lock.lock();
    try {
      return slot.body.motion().getVel();
    } finally {
      world.lock.unlock();
    }
  }

  /** Rotational velocity, deg/s. */
  public double getRotVel() {
    world.lock.lock();
    try {
      return slot.body.motion().getRotVel();
    } finally {
      world.lock.unlock();
    }
  }

  /** Whether the motors are enabled. */
  public boolean areMotorsEnabled() {
    world.lock.lock();
    try {
      return slot.body.motion().areMotorsEnabled();
    } finally {
      world.lock.unlock();
    }
  }

  /**
   * Stall and bumper bits of the last tick, as in the SIP (bits 0/8 stall, 1.. rear, 9.. front).
   */
  public int getStallAndBumpers() {
    world.lock.lock();
    try {
      return slot.body.getStallBits();
    } finally {
      world.lock.unlock();
    }
  }

  /** Whether the robot pushed against something in the last tick. */
  public boolean isStalled() {
    return (getStallAndBumpers() & (RobotBody.STALL_LEFT | RobotBody.STALL_RIGHT)) != 0;
  }

  /** Front bumper segments pressed in the last tick (bit i = segment i, 0 leftmost). */
  public int getFrontBumpers() {
    return (getStallAndBumpers() >> RobotBody.FRONT_BUMPER_SHIFT) & 0x7F;
  }

  /** Rear bumper segments pressed in the last tick (bit i = segment i). */
  public int getRearBumpers() {
    return (getStallAndBumpers() >> RobotBody.REAR_BUMPER_SHIFT) & 0x7F;
  }

  /** Ground truth of the last firing of every sonar transducer. */
  public List<SonarTruth> getSonarTruth() {
    world.lock.lock();
    try {
      List<SonarTruth> out = new ArrayList<>(slot.body.sonar().size());
      for (int i = 0; i < slot.body.sonar().size(); i++) {
        out.add(Views.sonarTruth(slot.body, i));
      }
      return out;
    } finally {
      world.lock.unlock();
    }
  }

  /** Ground truth of the last firing of transducer {@code i}. */
  public SonarTruth getSonarTruth(int i) {
    world.lock.lock();
    try {
      return Views.sonarTruth(slot.body, i);
    } finally {
      world.lock.unlock();
    }
  }

  /** The last laser scan, or null if the robot has no laser or has not scanned yet. */
  public SimLaserScan getLaserScan() {
    world.lock.lock();
    try {
      return Views.laser(slot.body);
    } finally {
      world.lock.unlock();
    }
  }

  /** The GRIP_STATE bits, or 0 without a gripper. */
  public int getGripState() {
    world.lock.lock();
    try {
      return slot.body.gripper() != null ? slot.body.gripper().state() : 0;
    } finally {
      world.lock.unlock();
    }
  }

  /**
   * Where the pan-tilt head on AUX1 points (see {@link RobotOptions#ptzType()}), or null if that
   * port holds no such device.
   */
  @Override
  public PtzHead.Pointing getPtzPointing() {
    world.lock.lock();
    try {
      return slot.body.auxPort(1).device() instanceof PtzHead h ? h.pointing() : null;
    } finally {
      world.lock.unlock();
    }
  }

  /** The name of the device on AUX1 ({@code vcc4}, {@code sony}, {@code dpptu}), or null. */
  public String getAuxDeviceName() {
    world.lock.lock();
    try {
      AuxSerialDevice d = slot.body.auxPort(1).device();
      return d == null ? null : d.name();
    } finally {
      world.lock.unlock();
    }
  }

  /** Sets the digital inputs the robot reports. */
  public void setDigitalInputs(int bits) {
    world.lock.lock();
    try {
      slot.body.io().setDigIn(bits);
    } finally {
      world.lock.unlock();
    }
  }

  /** Sets analog port {@code port} (0..7) to {@code value} (0..1023). */
  public void setAnalog(int port, int value) {
    world.lock.lock();
    try {
      slot.body.io().setAnalog(port, value);
    } finally {
      world.lock.unlock();
    }
  }

  /** The digital outputs the client set with DIGOUT. */
  public int getDigitalOutputs() {
    world.lock.lock();
    try {
      return slot.body.io().getDigOut();
    } finally {
      world.lock.unlock();
    }
  }

  /** A picture of this robot for drawing. */
  public SimSnapshot.RobotView view() {
    world.lock.lock();
    try {
      return Views.robot(slot);
    } finally {
      world.lock.unlock();
    }
  }

  /** Its slot in the world (for the world). */
  RobotSlot slot() {
    return slot;
  }

  /** Direct access for this package's tests and tools (call under the world's lock). */
  RobotBody body() {
    return slot.body;
  }

  @Override
  public String toString() {
    return "SimRobot[" + getName() + "]";
  }
}
