package org.jaria.web.server;

import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.jaria.geom.ArPose;
import org.jaria.web.model.ClockFrame;
import org.jaria.web.model.MapLayer;
import org.jaria.web.model.Points;
import org.jaria.web.model.RobotFrame;
import org.jaria.web.model.RobotStatus;
import org.jaria.web.model.WorldFrame;
import org.jaria.web.source.FrameSource;

/** A source of made-up frames: one robot, time advancing 100 ms per frame. */
final class FakeSource implements FrameSource {

  static final MapLayer MAP =
      new MapLayer(
          "fake",
          Points.of(0, 0, 5000, 0),
          Points.EMPTY,
          List.of(),
          Points.EMPTY,
          List.of(),
          MapLayer.Bounds.around(Points.of(0, 0, 5000, 0)));

  private final AtomicLong frames = new AtomicLong();
  private final int particles;

  /**
   * @param particles how many particles each frame carries (large frames for slow-reader tests)
   */
  FakeSource(int particles) {
    this.particles = particles;
  }

  @Override
  public MapLayer map() {
    return MAP;
  }

  @Override
  public WorldFrame frame() {
    long n = frames.incrementAndGet();
    Points.Builder p = Points.builder(particles);
    for (int i = 0; i < particles; i++) {
      p.add(i, -i);
    }
    RobotFrame r =
        new RobotFrame(
            "robot",
            "p3dx-sh",
            new ArPose(n, 0, 0),
            particles > 0 ? new ArPose(n, 0, 0) : null,
            Points.EMPTY,
            Points.EMPTY,
            Points.EMPTY,
            null,
            p.build(),
            Points.EMPTY,
            null,
            new RobotStatus(0, 0, Double.NaN, true, false, "test", Double.NaN));
    return new WorldFrame(new ClockFrame(n * 100_000_000L, 1, false, true), List.of(r));
  }
}
