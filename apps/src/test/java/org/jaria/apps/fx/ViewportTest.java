package org.jaria.apps.fx;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

class ViewportTest {

  private static Viewport vp() {
    Viewport v = new Viewport();
    v.setSize(800, 600);
    v.setScale(0.05);
    v.setCenter(1000, -2000);
    return v;
  }

  @Test
  void screenAndWorldAreInverseAndYPointsUp() {
    Viewport v = vp();
    assertEquals(400, v.toScreenX(1000), 1e-9);
    assertEquals(300, v.toScreenY(-2000), 1e-9);
    assertTrue(v.toScreenY(0) < v.toScreenY(-1000), "larger y is higher on screen");
    Random r = new Random(7);
    for (int i = 0; i < 100; i++) {
      double x = r.nextDouble() * 1e5 - 5e4;
      double y = r.nextDouble() * 1e5 - 5e4;
      assertEquals(x, v.toWorldX(v.toScreenX(x)), 1e-6);
      assertEquals(y, v.toWorldY(v.toScreenY(y)), 1e-6);
    }
  }

  @Test
  void zoomKeepsThePointUnderTheMouse() {
    Viewport v = vp();
    double wx = v.toWorldX(123);
    double wy = v.toWorldY(456);
    v.zoomAt(2.5, 123, 456);
    assertEquals(0.125, v.scale(), 1e-12);
    assertEquals(wx, v.toWorldX(123), 1e-6);
    assertEquals(wy, v.toWorldY(456), 1e-6);
  }

  @Test
  void zoomIsClamped() {
    Viewport v = vp();
    v.setScale(1e9);
    assertEquals(Viewport.MAX_SCALE, v.scale());
    v.setScale(0);
    assertEquals(Viewport.MIN_SCALE, v.scale());
  }

  @Test
  void panFollowsTheMouse() {
    Viewport v = vp();
    double wx = v.toWorldX(100);
    double wy = v.toWorldY(100);
    v.panPixels(30, -40);
    assertEquals(wx, v.toWorldX(130), 1e-9);
    assertEquals(wy, v.toWorldY(60), 1e-9);
  }

  @Test
  void fitShowsTheWholeBox() {
    Viewport v = vp();
    v.fit(-5000, -27000, 20000, 25000, 20);
    assertTrue(v.toScreenX(-5000) >= 19.99 && v.toScreenX(20000) <= 780.01);
    assertTrue(v.toScreenY(25000) >= 19.99 && v.toScreenY(-27000) <= 580.01);
    assertTrue(v.intersects(0, 0, 1, 1));
    assertFalse(v.intersects(1e6, 1e6, 1e6 + 1, 1e6 + 1));
  }
}
