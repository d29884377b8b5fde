package org.jaria.apps.fx;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.prefs.BackingStoreException;
import java.util.prefs.Preferences;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Small settings an app remembers between runs: window position and size, the last folder, view
 * options. Each app has its own store; {@link #forApp(String)} keeps it in the user's {@link
 * Preferences} (node {@code org/jaria/tools/<app>}), and {@link #inMemory()} keeps it only while
 * the program runs, which is what tests and {@code jaria screenshot} use so they neither depend on
 * nor change the user's real settings.
 */
public interface AppPrefs {

  /** The stored text for {@code key}, or {@code def} if there is none. */
  String get(String key, String def);

  /** Stores {@code value} under {@code key}. */
  void put(String key, String value);

  /** Writes pending changes to permanent storage, if the store has any. */
  default void flush() {}

  /** The stored number for {@code key}, or {@code def} if there is none or it is not a number. */
  default double getDouble(String key, double def) {
    String s = get(key, null);
    if (s == null) {
      return def;
    }
    try {
      return Double.parseDouble(s);
    } catch (NumberFormatException e) {
      return def;
    }
  }

  /** Stores a number. */
  default void putDouble(String key, double value) {
    put(key, Double.toString(value));
  }

  /** The stored flag for {@code key}, or {@code def}. */
  default boolean getBoolean(String key, boolean def) {
    String s = get(key, null);
    return s == null ? def : Boolean.parseBoolean(s);
  }

  /** Stores a flag. */
  default void putBoolean(String key, boolean value) {
    put(key, Boolean.toString(value));
  }

  /**
   * These settings seen through a key prefix: {@code scoped("eztrain.").get("window.x")} reads
   * "eztrain.window.x" here. Lets one app keep another's settings apart from its own.
   */
  default AppPrefs scoped(String prefix) {
    AppPrefs outer = this;
    return new AppPrefs() {
      @Override
      public String get(String key, String def) {
        return outer.get(prefix + key, def);
      }

      @Override
      public void put(String key, String value) {
        outer.put(prefix + key, value);
      }

      @Override
      public void flush() {
        outer.flush();
      }
    };
  }

  /** The user's permanent settings of app {@code appName} (e.g. "mapper"). */
  static AppPrefs forApp(String appName) {
    return new JavaPrefs(Preferences.userRoot().node("org/jaria/tools/" + appName));
  }

  /** Settings kept only in memory (tests, screenshots). */
  static AppPrefs inMemory() {
    return new MemoryPrefs();
  }

  /** {@link AppPrefs} on a {@link Preferences} node. */
  final class JavaPrefs implements AppPrefs {
    private static final Logger LOG = LoggerFactory.getLogger(JavaPrefs.class);
    private final Preferences node;

    /** A store on {@code node}. */
    public JavaPrefs(Preferences node) {
      this.node = node;
    }

    @Override
    public String get(String key, String def) {
      return node.get(key, def);
    }

    @Override
    public void put(String key, String value) {
      node.put(key, value);
    }

    @Override
    public void flush() {
      try {
        node.flush();
      } catch (BackingStoreException e) {
        // Losing a window position is not worth bothering the user with a dialog.
        LOG.warn("could not save settings to {}: {}", node.absolutePath(), e.getMessage());
      }
    }
  }

  /** {@link AppPrefs} in a map. */
  final class MemoryPrefs implements AppPrefs {
    private final Map<String, String> values = new ConcurrentHashMap<>();

    @Override
    public String get(String key, String def) {
      return values.getOrDefault(key, def);
    }

    @Override
    public void put(String key, String value) {
      values.put(key, value);
    }
  }
}
