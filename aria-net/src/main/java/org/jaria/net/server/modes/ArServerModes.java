package org.jaria.net.server.modes;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.jaria.net.server.ArServerBase;

/**
 * The server modes of one server and which one is active (ArNetworking keeps this in {@code
 * ArServerMode}'s static members; here it belongs to the server). Switching happens on the robot's
 * cycle; the active mode's name and status may be read from any thread.
 */
public final class ArServerModes {

  /** Name of the cycle task that runs the active mode. */
  public static final String CYCLE_TASK = "ArServerModes";

  private final List<ArServerMode> modes = new CopyOnWriteArrayList<>();
  private volatile ArServerMode active;
  private volatile ArServerMode defaultMode;

  private ArServerModes(ArServerBase server) {
    server.addCycleTask(CYCLE_TASK, this::cycle);
  }

  /** The registry of {@code server}, made on first use. */
  public static ArServerModes of(ArServerBase server) {
    return server.getService(ArServerModes.class, () -> new ArServerModes(server));
  }

  void add(ArServerMode m) {
    modes.add(m);
  }

  void setDefault(ArServerMode m) {
    defaultMode = m;
  }

  /** Makes {@code m} the active mode (cycle thread): the previous one is deactivated first. */
  void activate(ArServerMode m) {
    ArServerMode old = active;
    if (old == m) {
      return;
    }
    if (old != null) {
      old.doDeactivate();
    }
    active = m;
    m.doActivate();
  }

  /** {@code m} stops being active (cycle thread); the default mode takes over next cycle. */
  void deactivate(ArServerMode m) {
    if (active == m) {
      m.doDeactivate();
      active = null;
    }
  }

  private void cycle() {
    ArServerMode m = active;
    if (m == null) {
      ArServerMode d = defaultMode;
      if (d != null) {
        activate(d);
        m = d;
      }
    }
    if (m != null) {
      m.userTask();
    }
  }

  /** The active mode, or null. */
  public ArServerMode getActiveMode() {
    return active;
  }

  /** The default mode, or null. */
  public ArServerMode getDefaultMode() {
    return defaultMode;
  }

  /** The active mode's mode string ("Stop", "Drive" ...), or "None". */
  public String getMode() {
    ArServerMode m = active;
    return m == null ? "None" : m.getMode();
  }

  /** The active mode's status ("Stopped", "Wandering" ...), or "". */
  public String getStatus() {
    ArServerMode m = active;
    return m == null ? "" : m.getStatus();
  }

  /** Every mode registered with the server. */
  public List<ArServerMode> getModes() {
    return List.copyOf(modes);
  }
}
