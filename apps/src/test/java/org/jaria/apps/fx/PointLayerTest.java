package org.jaria.apps.fx;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.BitSet;
import java.util.Random;
import javafx.scene.image.PixelFormat;
import javafx.scene.image.WritableImage;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.testfx.framework.junit5.ApplicationExtension;

/** The culled, bucketed point renderer draws exactly what a brute-force loop would. */
@Tag("gui")
@ExtendWith(ApplicationExtension.class)
class PointLayerTest {

  private static final int N = 20_000;

  private final int[] xs = new int[N];
  private final int[] ys = new int[N];

  PointLayerTest() {
    Random r = new Random(42);
    for (int i = 0; i < N; i++) {
      xs[i] = r.nextInt(50_000) - 20_000;
      ys[i] = (int) (r.nextGaussian() * 8000);
    }
  }

  private static int[] pixels(WritableImage img) {
    int w = (int) img.getWidth();
    int h = (int) img.getHeight();
    int[] px = new int[w * h];
    img.getPixelReader().getPixels(0, 0, w, h, PixelFormat.getIntArgbInstance(), px, 0, w);
    return px;
  }

  /** What a plain loop over every point draws (1-pixel dots). */
  private int[] bruteForce(Viewport vp) {
    int w = (int) vp.width();
    int h = (int) vp.height();
    int[] px = new int[w * h];
    double s = vp.scale();
    double ox = vp.width() / 2 - vp.centerX() * s;
    double oy = vp.height() / 2 + vp.centerY() * s;
    for (int i = 0; i < N; i++) {
      int x = (int) (xs[i] * s + ox);
      int y = (int) (oy - ys[i] * s);
      if (x >= 0 && y >= 0 && x < w && y < h) {
        px[y * w + x] = 0xFF000000;
      }
    }
    return px;
  }

  @Test
  void culledRenderingMatchesBruteForceAtManyViews() {
    PointLayer layer = new PointLayer(xs, ys);
    Random r = new Random(1);
    for (int k = 0; k < 25; k++) {
      Viewport vp = new Viewport();
      vp.setSize(200 + r.nextInt(300), 150 + r.nextInt(200));
      vp.setScale(Math.pow(10, -3 + 2.5 * r.nextDouble()));
      vp.setCenter(r.nextInt(80_000) - 40_000, r.nextInt(60_000) - 30_000);
      // A 1 mm point size keeps dots 1 pixel at every zoom used here (< 0.5 px/mm).
      int[] got = pixels(layer.render(vp, 0xFF000000, null, 0, 1));
      assertArrayEquals(bruteForce(vp), got, "view " + k);
    }
  }

  /** Points at (0, 0) and (1000, 0). */
  private static PointLayer twoPoints() {
    return new PointLayer(new int[] {0, 1000}, new int[] {0, 0});
  }

  /**
   * A 100x100 view at 0.1 px/mm centred on (500, 0): the two points at its left and right edges.
   */
  private static Viewport tenthOfAPixelPerMm() {
    Viewport vp = new Viewport();
    vp.setSize(100, 100);
    vp.setScale(0.1);
    vp.setCenter(500, 0);
    return vp;
  }

  @Test
  void selectedPointsTakeTheirColourAndBigDotsStayInside() {
    PointLayer layer = twoPoints();
    Viewport vp = tenthOfAPixelPerMm();
    BitSet sel = new BitSet();
    sel.set(1);
    int[] px = pixels(layer.render(vp, 0xFF000000, sel, 0xFF0000FF, 40));
    assertEquals(0xFF000000, px[50 * 100 + 0]);
    assertEquals(0xFF0000FF, px[50 * 100 + 99]);
    assertEquals(0xFF0000FF, px[48 * 100 + 98], "4-pixel dots (40 mm at 0.1 px/mm)");
  }

  @Test
  void boxSelectionAndNearestMatchBruteForce() {
    PointLayer layer = new PointLayer(xs, ys);
    BitSet got = new BitSet();
    layer.select(-3000, -2000, 4000, 1500, got);
    BitSet want = new BitSet();
    for (int i = 0; i < N; i++) {
      if (xs[i] >= -3000 && xs[i] <= 4000 && ys[i] >= -2000 && ys[i] <= 1500) {
        want.set(i);
      }
    }
    assertEquals(want, got);
    assertTrue(want.cardinality() > 100);
    int i = layer.nearest(xs[77] + 1, ys[77], 5);
    assertEquals(xs[77], xs[i]);
    assertEquals(ys[77], ys[i]);
    assertEquals(-1, layer.nearest(1e7, 1e7, 10));
  }

  @Test
  void anUnchangedViewIsNotDrawnAgainAndAnyChangeIs() {
    PointLayer layer = twoPoints();
    Viewport vp = tenthOfAPixelPerMm();
    BitSet sel = new BitSet();
    WritableImage first = layer.render(vp, 0xFF000000, sel, 0xFF0000FF, 40);
    // A mark the layer never draws: it survives only if the image is not drawn again.
    first.getPixelWriter().setArgb(10, 10, 0xFF00FF00);
    assertSame(first, layer.render(vp, 0xFF000000, sel, 0xFF0000FF, 40));
    assertEquals(0xFF00FF00, pixels(first)[10 * 100 + 10], "nothing changed: not drawn again");

    sel.set(1); // the caller changes its selection in place
    int[] px = pixels(layer.render(vp, 0xFF000000, sel, 0xFF0000FF, 40));
    assertEquals(0, px[10 * 100 + 10], "the selection changed: drawn again");
    assertEquals(0xFF0000FF, px[50 * 100 + 99]);

    first.getPixelWriter().setArgb(10, 10, 0xFF00FF00);
    vp.setCenter(501, 0);
    assertEquals(0, pixels(layer.render(vp, 0xFF000000, sel, 0xFF0000FF, 40))[10 * 100 + 10]);
    first.getPixelWriter().setArgb(10, 10, 0xFF00FF00);
    assertEquals(0, pixels(layer.render(vp, 0xFF101010, sel, 0xFF0000FF, 40))[10 * 100 + 10]);
  }
}
