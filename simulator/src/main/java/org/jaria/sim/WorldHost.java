package org.jaria.sim;

import org.jaria.clock.Clock;
import org.jaria.protocol.ArCommands;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.sim.server.ArcosSession;
import org.jaria.sim.server.CommandPolicy;
import org.jaria.sim.server.IgnoredCommand;
import org.jaria.sim.server.ServerPackets;
import org.jaria.sim.server.SessionHost;
import org.jaria.sim.world.WorldGeometry;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/** The world as its robots' sessions see it; every call comes from the stepping thread. */
final class WorldHost implements SessionHost {

  private static final Logger log = LoggerFactory.getLogger(WorldHost.class);

  private final SimWorld world;

  WorldHost(SimWorld world) {
    this.world = world;
  }

  @Override
  public Clock clock() {
    return world.getClock();
  }

  @Override
  public WorldGeometry world() {
    return world.geometry();
  }

  @Override
  public int sipCycleMillis() {
    return world.getOptions().sipCycleMillis();
  }

  @Override
  public int watchdogMillis() {
    return world.getOptions().watchdogMillis();
  }

  @Override
  public boolean watchdogWarnOnly() {
    return world.getOptions().watchdogWarnOnly();
  }

  @Override
  public void ignoredCommand(int command, IgnoredCommand.Reason reason, String robotName) {
    if (!world.ignoredCommands().record(command, reason)) {
      return;
    }
    ArCommands c = ArCommands.fromNumber(command);
    String what = c == null ? "command " + command : "command " + command + " (" + c + ")";
    switch (reason) {
      case UNKNOWN ->
          log.warn("{}: {} is not an ARCOS command; ignored (logged once)", robotName, what);
      case NOT_SIMULATED ->
          log.warn(
              "{}: {} is not simulated (no such device in the simulator); ignored (logged once)",
              robotName,
              what);
      case BY_OPTION ->
          log.info("{}: {} ignored as the options ask (logged once)", robotName, what);
      case NOT_IN_MOBILESIM ->
          log.info(
              "{}: {} ignored, as MobileSim ignores it (the mobilesim profile; logged once)",
              robotName,
              what);
      case REMOTE_CLIENT ->
          log.warn(
              "{}: {} refused: only clients on this machine may send it (logged once); see"
                  + " docs/simulator.md, Hostile clients and safe defaults",
              robotName,
              what);
      case NO_DEVICE ->
          log.warn(
              "{}: {} needs a device this robot does not carry; ignored (logged once). Give the"
                  + " robot the device (RobotOptions.withLaser/withGyro/withGripper, or --laser)",
              robotName,
              what);
    }
  }

  @Override
  public void loadMapRequested(String path, int robotIndex) {
    RobotSlot asker = world.slotByNumber(robotIndex);
    if (asker == null) {
      return; // the robot left the world while its command was being read
    }
    if (!world.mapLoader().submit(path, robotIndex, asker.body.name())) {
      log.warn(
          "{}: client map '{}' refused: another map is still loading",
          asker.body.name(),
          ClientMapFolder.printable(path));
      answer(asker, -1, path);
    }
  }

  /**
   * Applies a map a client asked for once it is loaded: every client hears of a new map; only the
   * asking client hears of a failure.
   */
  void mapLoadFinished(ClientMapLoader.Result r) {
    if (r.map() == null) {
      RobotSlot asker = world.slotByNumber(r.robotIndex());
      if (asker != null) { // not if the robot left the world while its map loaded
        answer(asker, -1, r.requested());
      }
      return;
    }
    world.setMap(r.map());
    for (RobotSlot s : world.slots()) {
      answer(s, 1, r.requested());
    }
  }

  private static void answer(RobotSlot s, int status, String name) {
    ArcosSession holder = s.session();
    if (holder != null) {
      ArRobotPacket p = new ArRobotPacket();
      ServerPackets.mapChanged(p, false, status, name);
      holder.sendPacket(p);
    }
  }

  @Override
  public CommandPolicy commandPolicy() {
    return world.commandPolicy();
  }

  @Override
  public int handshakeTimeoutMillis() {
    return HandshakeTime.simulatedMillis(
        world.getOptions().server().handshakeTimeoutMillis(), world.speedup());
  }

  @Override
  public int clientTimeoutMillis() {
    return world.getOptions().server().clientTimeoutMillis();
  }

  @Override
  public int replaceSilentMillis() {
    return world.getOptions().server().replaceSilentMillis();
  }

  @Override
  public void exitRequested(int code, String robotName) {
    log.info("{}: client asks the simulator to exit with code {}", robotName, code);
    world.exitHandler().accept(code);
  }

  @Override
  public void ghostRequested(int robotIndex) {
    world.geometry().setSolid(robotIndex, false);
  }

  @Override
  public boolean haveMap() {
    return world.haveMap();
  }

  @Override
  public int simIntervalMillis() {
    return (int) world.getTick().toMillis();
  }

  @Override
  public int realIntervalMillis() {
    return world.realIntervalMillis();
  }

  @Override
  public int lastIntervalMillis() {
    return world.lastIntervalMillis();
  }
}
