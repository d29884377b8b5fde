package org.jaria.sim.serial;

import java.util.List;
import java.util.Locale;

/**
 * The devices the simulator can put on a robot's AUX1 port, by the type names ARIA's {@code
 * PTZType} robot parameter uses: {@code vcc4} (Canon VC-C4, the default), {@code sony} (Sony
 * EVI-D30/D70 over VISCA), {@code dpptu} (Directed Perception PTU-46-17.5) and {@code none}.
 */
public final class AuxDevices {

  /** The type names {@link #create} knows, in the order help texts list them. */
  public static final List<String> PTZ_TYPES = List.of("vcc4", "sony", "dpptu", "none");

  private AuxDevices() {}

  /**
   * A new device of {@code type} (case-insensitive), or null for {@code none}.
   *
   * @throws IllegalArgumentException for a name not in {@link #PTZ_TYPES}
   */
  public static AuxSerialDevice create(String type) {
    return switch (normalize(type)) {
      case "vcc4" -> new Vcc4Camera();
      case "sony" -> new SonyEviCamera();
      case "dpptu" -> new DpPtu();
      default -> null;
    };
  }

  /**
   * {@code type} trimmed and lower-cased.
   *
   * @throws IllegalArgumentException for a name not in {@link #PTZ_TYPES}
   */
  public static String normalize(String type) {
    String t = type == null ? "" : type.trim().toLowerCase(Locale.ROOT);
    if (!PTZ_TYPES.contains(t)) {
      throw new IllegalArgumentException(
          "unknown PTZ type '" + type + "': use one of " + String.join(", ", PTZ_TYPES));
    }
    return t;
  }
}
