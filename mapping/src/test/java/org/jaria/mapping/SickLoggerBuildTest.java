package org.jaria.mapping;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.jaria.geom.ArPose;
import org.jaria.map.ArMap;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Maps built from logs ARIA's own sickLogger wrote (driven through the office by its arrow keys,
 * against {@code jaria sim} and against AMRISim) fit the office's walls. The robot started at the
 * office's home, so the log's frame lies there.
 */
class SickLoggerBuildTest {

  @ParameterizedTest
  @ValueSource(strings = {"sicklogger-jaria-sim.2d", "sicklogger-amrisim.2d"})
  void realSickLoggerLogsBuildMapsThatFitTheWalls(String file) throws Exception {
    BuiltMap m = MapBuilderTest.build(MapBuilderTest.resource(file));
    ArMap office = ArMap.loadBundled("office");
    ArPose home = office.findHomePose().orElseThrow();
    ArPose toTruth = Poses.compose(home, Poses.inverse(m.trajectory().pose(0)));
    double near = MapQuality.nearWalls(m, office, toTruth, 50);
    assertTrue(near >= 0.95, file + ": points within 50 mm of a wall " + near);
    assertTrue(m.toArMap().findMapObject("goal1").isPresent(), "the goal placed on the way");
    assertTrue(m.lines().size() >= 5, "walls: " + m.lines().size());
  }
}
