package org.jaria.net.server.modes;

import java.util.Locale;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.net.protocol.NetError;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.NetRequestException;
import org.jaria.net.server.Where;

/**
 * ARNL's {@code "dock"} request, answered as unsupported. ARNL's {@code ArServerModeDock} drives to
 * a charging station, senses it and backs onto its contacts; neither MobileSim nor JAria's
 * simulator simulates a charger (a map's {@code Dock} is only a place; MobileSim reports "not
 * charging" forever), and JAria has no docking driver for a real one. So {@code "dock"} is listed,
 * as clients look for it, and every request fails with JAria's {@code requestFailed} (UNAVAILABLE)
 * saying where the map's dock is and that {@code gotoPose} drives there. ARIA's clients, which do
 * not know {@code requestFailed}, see nothing happen. The mode never activates.
 */
public final class ArServerModeDock {

  private volatile ArMap map;

  /** Registers {@code "dock"} with {@code server}; {@code map} may be null. */
  public ArServerModeDock(ArServerBase server, ArMap map) {
    this.map = map;
    server.addData(
        "dock",
        "Enter dock mode and send the robot to the docking station (JAria: unsupported, no"
            + " charger is simulated)",
        "none",
        "none",
        "Movement",
        Where.WORKER,
        (client, request, reply) -> {
          throw new NetRequestException(NetError.UNAVAILABLE, refusal(this.map));
        });
  }

  /** Names the dock of another map from now on (after a map change). */
  public void setMap(ArMap m) {
    map = m;
  }

  /** Why docking is refused, naming the map's dock if it has one. */
  static String refusal(ArMap map) {
    String where =
        map == null
            ? "there is no map"
            : map.findFirstMapObjectOfType("Dock")
                .map(ArMapObject::pose)
                .map(
                    p ->
                        String.format(
                            Locale.ROOT,
                            "the map's Dock is at (%.0f, %.0f): gotoPose drives there",
                            p.getX(),
                            p.getY()))
                .orElse("the map has no Dock");
    return "docking is not supported: no charging station is simulated or driven; " + where;
  }
}
