package org.jaria.arnl.bench;

import java.io.StringReader;
import java.util.List;
import org.jaria.geom.ArPose;
import org.jaria.laser.log.LoggedScan;
import org.jaria.laser.log.ScanLogEntry;
import org.jaria.laser.log.ScanLogReader;
import org.jaria.map.ArMap;
import org.jaria.mapping.BuiltMap;
import org.jaria.mapping.MapBuilder;
import org.jaria.mapping.MapBuilderParams;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;

@Tag("experiment")
class MappingDebugTest {
  @Test
  void office() throws Exception {
    ArMap office = ArMap.loadBundled("office");
    MappingBench.Drive d = MappingBench.drive(office, BenchSupport.officeLaps(1), 11);
    BuiltMap m;
    try (ScanLogReader r = new ScanLogReader(new StringReader(d.log()), "x")) {
      MapBuilder b = new MapBuilder(r.header(), MapBuilderParams.DEFAULTS);
      for (ScanLogEntry e = r.next(); e != null; e = r.next()) {
        b.add(e);
        if (e instanceof LoggedScan s && s.id() < 6) {
          System.out.println(s.id() + " odo " + s.robotPose() + " true " + d.trueLaser().get(s.id()));
        }
      }
      m = b.finish();
    }
    ArPose mount = new ArPose(21, 0, 0);
    ArPose t = TruthCompare.toTruth(m, d.trueLaser(), mount);
    System.out.println("toTruth " + t);
    for (int i = 16; i < 34; i += 1) {
      ArPose est = TruthCompare.compose(t, TruthCompare.compose(m.trajectory().pose(i), mount));
      System.out.println(i + " est " + est + " true " + d.trueLaser().get(m.trajectory().scanId(i)));
    }
  }
}
