package org.jaria.sim.camera;

import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.sim.serial.PtzHead;

/**
 * A pan/tilt/zoom colour camera on a simulated robot (like the Canon VC-C4 of the thesis). It
 * renders what it sees: walls in grey shaded by distance, the floor and ceiling, and the world's
 * {@link ColoredObjects} in their colours with shading and a little seeded noise, so that colour
 * training and blob tracking meet realistic pixels. One ray is cast per image column; rows come
 * from the heights of what the ray met.
 *
 * <p>Thread-safe: the pan/tilt/zoom state is volatile, and rendering only reads the world.
 */
public final class SimCamera {

  /** Wall height assumed for every map line, mm. */
  public static final double WALL_HEIGHT = 2200;

  /** Horizontal field of view with no zoom, degrees (VC-C4 wide end). */
  public static final double WIDE_FOV = 48.8;

  /** Largest zoom value; at this zoom the view is 16 times narrower. */
  public static final int MAX_ZOOM = 1023;

  private static final int FLOOR = 0x5A5650;
  private static final int CEILING = 0xCFD0D6;
  private static final int WALL = 0xB4B0A8;
  private static final int MAX_HITS = 16;

  private final CameraScene world;
  private final CameraMount robot;
  private final int width;
  private final int height;
  private final double mountX;
  private final double mountZ;
  private volatile double pan;
  private volatile double tilt;
  private volatile int zoom;
  private volatile boolean followAuxPtz;
  private long frame;
  private final long seed;

  /**
   * A camera of {@code width} × {@code height} pixels, {@code mountX} mm ahead of the robot's
   * centre and {@code mountZ} mm above the floor. {@code world} and {@code robot} are a {@code
   * SimWorld} and one of its {@code SimRobot}s.
   */
  public SimCamera(
      CameraScene world, CameraMount robot, int width, int height, double mountX, double mountZ) {
    if (width < 8 || height < 8) {
      throw new IllegalArgumentException(
          "camera image must be at least 8x8, got " + width + "x" + height);
    }
    this.world = world;
    this.robot = robot;
    this.width = width;
    this.height = height;
    this.mountX = mountX;
    this.mountZ = mountZ;
    this.seed = world.seed() * 31 + robot.getIndex();
  }

  /** A 160×120 camera on top of the robot, at the front, 450 mm up (a P3-DX with a VC-C4). */
  public static SimCamera onTop(CameraScene world, CameraMount robot) {
    return new SimCamera(world, robot, 160, 120, 100, 450);
  }

  /** Image width, pixels. */
  public int getWidth() {
    return width;
  }

  /** Image height, pixels. */
  public int getHeight() {
    return height;
  }

  /**
   * Points the camera: pan (+ right, ARIA's {@code ArPTZ} sign) and tilt (+ up), degrees; clamped
   * to ±100 and −30..90.
   */
  public void setPanTilt(double panDeg, double tiltDeg) {
    pan = Math.max(-100, Math.min(100, panDeg));
    tilt = Math.max(-30, Math.min(90, tiltDeg));
  }

  /** Sets the zoom, 0 (wide) .. {@link #MAX_ZOOM}. */
  public void setZoom(int z) {
    zoom = Math.max(0, Math.min(MAX_ZOOM, z));
  }

  /**
   * Makes the camera point wherever the pan-tilt head on the robot's AUX1 port points (a Sony,
   * Directed Perception or Canon unit driven over the wire), read each time the camera is used;
   * off, {@link #setPanTilt} points it.
   */
  public void setFollowAuxPtz(boolean on) {
    followAuxPtz = on;
  }

  private void followAux() {
    if (!followAuxPtz) {
      return;
    }
    PtzHead.Pointing p = robot.getPtzPointing();
    if (p != null) {
      setPanTilt(p.panRightDeg(), p.tiltUpDeg());
      setZoom((int) Math.round(p.zoomFraction() * MAX_ZOOM));
    }
  }

  /** Pan, degrees, positive to the right. */
  public double getPan() {
    followAux();
    return pan;
  }

  /** Tilt, degrees. */
  public double getTilt() {
    followAux();
    return tilt;
  }

  /** Zoom, 0 .. {@link #MAX_ZOOM}. */
  public int getZoom() {
    followAux();
    return zoom;
  }

  /** The current horizontal field of view, degrees. */
  public double getFovDegrees() {
    return WIDE_FOV / (1 + 15.0 * zoom / MAX_ZOOM);
  }

  /** Where the camera is and which way it looks (pan included), in world coordinates. */
  public ArPose getViewPose() {
    followAux();
    ArPose p = robot.getTruePose();
    double r = Math.toRadians(p.th());
    // Headings grow counter-clockwise (to the left); the pan is positive to the right.
    return new ArPose(p.x() + mountX * Math.cos(r), p.y() + mountX * Math.sin(r), p.th() - pan);
  }

  /**
   * Renders the current view into {@code rgb} (width × height pixels, row by row, each 0xRRGGBB).
   */
  public void render(int[] rgb) {
    if (rgb.length < width * height) {
      throw new IllegalArgumentException("frame buffer too small: " + rgb.length);
    }
    ArPose view = getViewPose();
    double fov = Math.toRadians(getFovDegrees());
    double focal = (width / 2.0) / Math.tan(fov / 2);
    double tiltRad = Math.toRadians(tilt);
    List<ColoredObject> objects = world.coloredObjects().list();
    double[] hitDist = new double[MAX_HITS];
    double[] hitBottom = new double[MAX_HITS];
    double[] hitTop = new double[MAX_HITS];
    int[] hitColor = new int[MAX_HITS];
    double[] normal = new double[2];
    long noise = seed ^ (++frame * 0x9E3779B97F4A7C15L);
    for (int col = 0; col < width; col++) {
      double angle = view.th() + Math.toDegrees(Math.atan(((width / 2.0) - col - 0.5) / focal));
      double a = Math.toRadians(angle);
      double dx = Math.cos(a);
      double dy = Math.sin(a);
      int n = 0;
      double wall = world.castRay(view.x(), view.y(), angle, 20000, robot.getIndex());
      for (ColoredObject o : objects) {
        double d = o.intersect(view.x(), view.y(), dx, dy, normal);
        if (!Double.isNaN(d) && d < wall && n < MAX_HITS - 1) {
          double lambert = Math.max(0.35, -(normal[0] * dx + normal[1] * dy));
          hitDist[n] = d;
          hitBottom[n] = o.bottom();
          hitTop[n] = o.top();
          hitColor[n] = shade(o.rgb(), lambert * distanceShade(d));
          n++;
        }
      }
      if (!Double.isInfinite(wall)) {
        hitDist[n] = wall;
        hitBottom[n] = 0;
        hitTop[n] = WALL_HEIGHT;
        hitColor[n] = shade(WALL, distanceShade(wall));
        n++;
      }
      sortByDistance(hitDist, hitBottom, hitTop, hitColor, n);
      for (int row = 0; row < height; row++) {
        double elev = tiltRad + Math.atan(((height / 2.0) - row - 0.5) / focal);
        double slope = Math.tan(elev);
        int color = -1;
        for (int k = 0; k < n; k++) {
          double z = mountZ + slope * hitDist[k];
          if (z >= hitBottom[k] && z <= hitTop[k]) {
            color = hitColor[k];
            break;
          }
        }
        if (color < 0) {
          color = elev < 0 ? shade(FLOOR, distanceShade(mountZ / -slope)) : CEILING;
        }
        noise = noise * 6364136223846793005L + 1442695040888963407L;
        rgb[row * width + col] = jitter(color, (int) (noise >>> 40));
      }
    }
  }

  private static double distanceShade(double d) {
    return 1.0 - Math.min(0.55, d / 16000.0);
  }

  private static int shade(int rgb, double f) {
    int r = (int) (((rgb >> 16) & 0xFF) * f);
    int g = (int) (((rgb >> 8) & 0xFF) * f);
    int b = (int) ((rgb & 0xFF) * f);
    return (r << 16) | (g << 8) | b;
  }

  /** Adds up to ±4 of noise per channel, like a cheap camera. */
  private static int jitter(int rgb, int bits) {
    int r = clamp(((rgb >> 16) & 0xFF) + (bits & 7) - 4);
    int g = clamp(((rgb >> 8) & 0xFF) + ((bits >> 3) & 7) - 4);
    int b = clamp((rgb & 0xFF) + ((bits >> 6) & 7) - 4);
    return (r << 16) | (g << 8) | b;
  }

  private static int clamp(int v) {
    return v < 0 ? 0 : Math.min(255, v);
  }

  private static void sortByDistance(double[] d, double[] lo, double[] hi, int[] c, int n) {
    for (int i = 1; i < n; i++) {
      for (int j = i; j > 0 && d[j - 1] > d[j]; j--) {
        swap(d, j);
        swap(lo, j);
        swap(hi, j);
        int t = c[j];
        c[j] = c[j - 1];
        c[j - 1] = t;
      }
    }
  }

  private static void swap(double[] a, int j) {
    double t = a[j];
    a[j] = a[j - 1];
    a[j - 1] = t;
  }
}
