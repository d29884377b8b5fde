package org.jaria.site.samples;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import org.jaria.map.ArMap;
import org.jaria.map.ArMapObject;
import org.jaria.map.MapFormatException;

/** Reading a map (the maps guide). */
public final class MapSample {

  private MapSample() {}

  /** Prints a map's extent and goals; reads a file, or a bundled map by name. */
  public static ArMap describe(String fileOrBundled, PrintStream out)
      throws IOException, MapFormatException {
    // tag::read[]
    ArMap map =
        ArMap.BUNDLED_MAPS.contains(fileOrBundled)
            ? ArMap.loadBundled(fileOrBundled) // "office" or "hall", shipped inside JAria
            : ArMap.readFile(Path.of(fileOrBundled)); // any .map file from Mapper3 or jaria mapper
    out.println(map.getLines().size() + " lines, " + map.getPoints().size() + " points");
    out.println("extent " + map.getLineMinPos() + " .. " + map.getLineMaxPos());
    map.findHomePose().ifPresent(home -> out.println("home " + home));
    for (ArMapObject goal : map.getGoals()) {
      out.println("goal '" + goal.name() + "' at " + goal.pose());
    }
    // end::read[]
    return map;
  }
}
