package org.jaria.apps.mapper;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.concurrent.atomic.AtomicLong;
import javafx.scene.image.WritableImage;
import org.jaria.apps.fx.FxRuntime;
import org.jaria.apps.fx.PointLayer;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.map.ArMapPoints;

/**
 * {@code jaria bench mapper}: how long the map editor takes to draw a frame of a big map while the
 * user zooms and pans, on Monocle's headless platform with JavaFX's software renderer (a desktop's
 * GPU pipeline is faster; this is the slowest case the editor meets).
 *
 * <p>The map is either a file or a generated floor plan of 60,000 points (a laser-built map the
 * size of columbia.map: rooms along corridors, points scattered along the walls, 500 lines, 30
 * goals). Each row times the same view change many times: "draw" is the editor's own work on the
 * JavaFX thread (culling, the points' image, lines, objects), "draw + pixels" adds rasterizing the
 * frame (a snapshot of the view, which the software renderer does on the same thread). The figures
 * are the median and the 95th percentile of the frames.
 */
public final class MapperBenchmark {

  /** Size of the view drawn, pixels. */
  static final int WIDTH = 1280;

  static final int HEIGHT = 800;

  private MapperBenchmark() {}

  /**
   * Runs the benchmark (starting a headless JavaFX if none runs) and returns the table.
   *
   * @param map a map file, or null for the generated 60,000-point map
   * @param frames frames timed per row
   */
  public static String run(Path map, int frames) throws Exception {
    FxRuntime.configureHeadless();
    FxRuntime.startup();
    long t0 = System.nanoTime();
    MapDocument doc;
    String name;
    if (map == null) {
      AtomicLong ids = new AtomicLong(1);
      doc = new MapDocument(MapFile.wrap(generate(60_000, 1), ids::getAndIncrement), null, ids);
      name = "generated floor plan";
    } else {
      AtomicLong ids = new AtomicLong(1);
      doc = new MapDocument(MapFile.read(map, ids::getAndIncrement), map, ids);
      name = String.valueOf(map.getFileName());
    }
    double loadMs = (System.nanoTime() - t0) / 1e6;
    MapContent c = doc.content();
    StringBuilder out = new StringBuilder();
    out.append(
        String.format(
            Locale.ROOT,
            "JAria map editor benchmark: %s, %d points, %d lines, %d objects; view %dx%d,"
                + " headless software rendering, %d frames a row%n",
            name,
            c.points().size(),
            c.lines().size(),
            c.objects().size(),
            WIDTH,
            HEIGHT,
            frames));
    out.append(
        String.format(Locale.ROOT, "%-44s %12s%n", "load (read or generate, number)", ms(loadMs)));
    long i0 = System.nanoTime();
    PointLayer layer = new PointLayer(c.points().xArray(), c.points().yArray());
    double indexMs = (System.nanoTime() - i0) / 1e6;
    out.append(
        String.format(
            Locale.ROOT, "%-44s %12s%n", "index the points (" + layer.size() + ")", ms(indexMs)));
    long v0 = System.nanoTime();
    int problems = new MapValidator().validate(c).size();
    out.append(
        String.format(
            Locale.ROOT,
            "%-44s %12s%n",
            "check the map (" + problems + " problems)",
            ms((System.nanoTime() - v0) / 1e6)));
    out.append(
        String.format(
            Locale.ROOT,
            "%-44s %12s %12s %12s %12s%n",
            "frame",
            "draw p50",
            "draw p95",
            "+pixels p50",
            "+pixels p95"));
    FxRuntime.run(() -> rows(out, doc, frames), 600);
    return out.toString();
  }

  private static String ms(double v) {
    return String.format(Locale.ROOT, "%.2f ms", v);
  }

  /** A view change between two frames. */
  private interface Move {
    void apply(MapView v, int frame);
  }

  private static void rows(StringBuilder out, MapDocument doc, int frames) {
    MapView view = new MapView(doc, new MapSelection());
    view.resize(WIDTH, HEIGHT);
    view.layout();
    view.fit();
    double fitScale = view.viewport().scale();
    double cx = view.viewport().centerX();
    double cy = view.viewport().centerY();
    WritableImage img = new WritableImage(WIDTH, HEIGHT);
    Move reset =
        (v, f) -> {
          v.viewport().setScale(fitScale);
          v.viewport().setCenter(cx, cy);
        };
    row(out, view, img, frames, "whole map in view (fit, not moved)", reset, (v, f) -> {});
    row(
        out,
        view,
        img,
        frames,
        "pan, whole map (8 px a frame)",
        reset,
        (v, f) -> v.viewport().panPixels((f / 20) % 2 == 0 ? 8 : -8, 3));
    row(
        out,
        view,
        img,
        frames,
        "zoom in and out with the wheel",
        reset,
        (v, f) ->
            v.viewport().zoomAt((f / 30) % 2 == 0 ? 1.08 : 1 / 1.08, WIDTH * 0.4, HEIGHT * 0.6));
    row(
        out,
        view,
        img,
        frames,
        "pan, zoomed in 8x (1 px = " + fmtMm(1 / (fitScale * 8)) + ")",
        (v, f) -> {
          reset.apply(v, f);
          v.viewport().zoomAt(8, WIDTH / 2.0, HEIGHT / 2.0);
        },
        (v, f) -> v.viewport().panPixels((f / 20) % 2 == 0 ? 12 : -12, 5));
    row(
        out,
        view,
        img,
        frames,
        "pan, zoomed in 60x (points as squares)",
        (v, f) -> {
          reset.apply(v, f);
          v.viewport().zoomAt(60, WIDTH / 2.0, HEIGHT / 2.0);
        },
        (v, f) -> v.viewport().panPixels((f / 20) % 2 == 0 ? 12 : -12, 5));
  }

  private static String fmtMm(double mm) {
    return MapRenderer.formatLength(mm);
  }

  private static void row(
      StringBuilder out,
      MapView view,
      WritableImage img,
      int frames,
      String name,
      Move setup,
      Move move) {
    setup.apply(view, 0);
    // Warm-up: the same frames once, untimed.
    for (int f = 0; f < frames; f++) {
      move.apply(view, f);
      view.paint();
      view.snapshot(null, img);
    }
    setup.apply(view, 0);
    long[] draw = new long[frames];
    long[] full = new long[frames];
    for (int f = 0; f < frames; f++) {
      move.apply(view, f);
      long a = System.nanoTime();
      view.paint();
      long b = System.nanoTime();
      view.snapshot(null, img);
      long d = System.nanoTime();
      draw[f] = b - a;
      full[f] = d - a;
    }
    out.append(
        String.format(
            Locale.ROOT,
            "%-44s %12s %12s %12s %12s%n",
            name,
            ms(pct(draw, 0.5)),
            ms(pct(draw, 0.95)),
            ms(pct(full, 0.5)),
            ms(pct(full, 0.95))));
  }

  private static double pct(long[] v, double q) {
    long[] s = v.clone();
    Arrays.sort(s);
    return s[(int) Math.min(s.length - 1, Math.floor(q * s.length))] / 1e6;
  }

  /**
   * A laser-built-looking floor plan: a 40 × 50 m block of rooms on both sides of two corridors,
   * {@code points} sensor points scattered (±15 mm) along the walls, the walls as lines, and goals
   * in the rooms. Deterministic for a given seed.
   */
  static ArMap generate(int points, long seed) {
    SplittableRandom rnd = new SplittableRandom(seed);
    List<ArLineSegment> walls = new ArrayList<>();
    // Outer walls and two corridors running north-south.
    walls.add(new ArLineSegment(0, 0, 40_000, 0));
    walls.add(new ArLineSegment(40_000, 0, 40_000, 50_000));
    walls.add(new ArLineSegment(40_000, 50_000, 0, 50_000));
    walls.add(new ArLineSegment(0, 50_000, 0, 0));
    List<ArMapObject> goals = new ArrayList<>();
    int[] corridors = {12_000, 28_000};
    for (int cx : corridors) {
      for (int side = -1; side <= 1; side += 2) {
        int wallX = cx + side * 1_200;
        int backX = cx + side * 7_000;
        for (int y = 0; y < 50_000; y += 4_000) {
          // Corridor wall with a 1 m door per room, and the room's side wall.
          walls.add(new ArLineSegment(wallX, y, wallX, y + 1_500));
          walls.add(new ArLineSegment(wallX, y + 2_500, wallX, y + 4_000));
          walls.add(new ArLineSegment(wallX, y, backX, y));
          if (goals.size() < 30) {
            goals.add(
                ArMapObject.goal("Room " + (goals.size() + 1), (wallX + backX) / 2.0, y + 2_000.0));
          }
        }
      }
    }
    // Clutter (desks, shelves): short segments inside the rooms.
    while (walls.size() < 500) {
      double x = rnd.nextDouble(500, 39_500);
      double y = rnd.nextDouble(500, 49_500);
      double a = rnd.nextInt(4) * Math.PI / 2;
      double len = rnd.nextDouble(400, 1_600);
      walls.add(new ArLineSegment(x, y, x + len * Math.cos(a), y + len * Math.sin(a)));
    }
    double total = 0;
    for (ArLineSegment s : walls) {
      total += s.length();
    }
    int[] xs = new int[points];
    int[] ys = new int[points];
    int n = 0;
    for (ArLineSegment s : walls) {
      int k = (int) Math.round(points * s.length() / total);
      for (int i = 0; i < k && n < points; i++) {
        double t = rnd.nextDouble();
        xs[n] = (int) Math.round(s.x1() + t * (s.x2() - s.x1()) + rnd.nextDouble(-15, 15));
        ys[n] = (int) Math.round(s.y1() + t * (s.y2() - s.y1()) + rnd.nextDouble(-15, 15));
        n++;
      }
    }
    while (n < points) {
      xs[n] = rnd.nextInt(0, 40_000);
      ys[n] = rnd.nextInt(0, 50_000);
      n++;
    }
    ArMap m = new ArMap();
    m.setLines(walls);
    m.setPoints(ArMapPoints.of(xs, ys));
    m.addMapObject(ArMapObject.robotHome("", 12_000, 1_000, 90));
    for (ArMapObject g : goals) {
      m.addMapObject(g);
    }
    return m;
  }
}
