package org.jaria.net.server.info;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.CopyOnWriteArrayList;
import org.jaria.net.data.CameraInfo;

/**
 * The robot's cameras and the requests that command each (ARIA's {@code ArCameraCollection}): a
 * program adds a camera, each camera handler adds its commands ({@link ArServerHandlerCamera} does
 * it itself), and {@link ArServerHandlerCameraCollection} lists them to clients, so that a client
 * finds "setCameraAbsCam1" without knowing the camera's name beforehand. Cameras and commands are
 * kept in name order, as ARIA does. Thread-safe.
 */
public final class ArCameraCollection {

  private record Camera(
      String type, String displayName, String displayType, Map<String, CameraInfo.Command> cmds) {}

  @GuardedBy("this")
  private final Map<String, Camera> cameras = new TreeMap<>();

  private final List<Runnable> modifiedCallbacks = new CopyOnWriteArrayList<>();

  /**
   * Adds a camera.
   *
   * @param name the suffix of its requests ("Cam1")
   * @param type its type ("VCC4")
   * @param displayName what people see ("Camera")
   * @param displayType the type people see
   * @return false if a camera of that name is already there
   */
  public boolean addCamera(String name, String type, String displayName, String displayType) {
    synchronized (this) {
      if (name == null || name.isEmpty() || cameras.containsKey(name)) {
        return false;
      }
      cameras.put(
          name,
          new Camera(nz(type), nz(displayName, name), nz(displayType, type), new TreeMap<>()));
    }
    modified();
    return true;
  }

  /**
   * Adds a command of camera {@code cameraName}: ArNetworking's command name ({@code
   * "setCameraAbs"}), the request that carries it out ({@code "setCameraAbsCam1"}) and the interval
   * a client should request it at (-1: only when needed).
   *
   * @return false if there is no such camera or it has that command already
   */
  public boolean addCameraCommand(
      String cameraName, String command, String requestName, int requestInterval) {
    synchronized (this) {
      Camera c = cameras.get(cameraName);
      if (c == null || c.cmds().containsKey(command)) {
        return false;
      }
      c.cmds().put(command, new CameraInfo.Command(command, requestName, requestInterval));
    }
    modified();
    return true;
  }

  /** Whether there is a camera called {@code name}. */
  public synchronized boolean exists(String name) {
    return cameras.containsKey(name);
  }

  /** The cameras with their commands, in name order. */
  public synchronized List<CameraInfo> getCameras() {
    List<CameraInfo> l = new ArrayList<>();
    for (Map.Entry<String, Camera> e : cameras.entrySet()) {
      Camera c = e.getValue();
      l.add(
          new CameraInfo(
              e.getKey(),
              c.type(),
              c.displayName(),
              c.displayType(),
              new ArrayList<>(c.cmds().values())));
    }
    return l;
  }

  /** Runs {@code callback} after every change (ARIA's {@code addModifiedCB}). */
  public void addModifiedCB(Runnable callback) {
    modifiedCallbacks.add(callback);
  }

  /** Removes a callback. */
  public void removeModifiedCB(Runnable callback) {
    modifiedCallbacks.remove(callback);
  }

  private void modified() {
    for (Runnable r : modifiedCallbacks) {
      r.run();
    }
  }

  private static String nz(String s) {
    return s == null ? "" : s;
  }

  private static String nz(String s, String otherwise) {
    return s == null || s.isEmpty() ? nz(otherwise) : s;
  }
}
