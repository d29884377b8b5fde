package org.jaria.map;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * One {@code MapInfo:} line: the declaration of a kind of map object or an argument, e.g. {@code
 * MapInfo: GoalType Name=Goal "Label=Goal"}, or {@code MapInfo: SectorType Name=BadGPSSector
 * "Desc=Area where GPS is unreliable" Shape=Plain}.
 *
 * @param typeClass the first word ("GoalType", "DockType", "SectorType", "BoundaryType", ...)
 * @param attributes the {@code Key=Value} pairs in file order, quotes removed (a word without
 *     {@code =} maps to ""); unmodifiable
 * @param rawLine the line as it appeared in the file
 */
public record MapInfoEntry(String typeClass, Map<String, String> attributes, String rawLine) {

  /** Copies the attributes, keeping their order. */
  public MapInfoEntry {
    attributes = Collections.unmodifiableMap(new LinkedHashMap<>(attributes));
  }

  /** The {@code Name=} attribute, or "" if there is none. */
  public String getName() {
    return attributes.getOrDefault("Name", "");
  }
}
