package org.jaria.mapping;

/**
 * What the map builder is told: the map's resolution, which readings it uses and how far it looks
 * for loop closures. {@link #DEFAULTS} suit a Pioneer with a SICK LMS-200 indoors.
 *
 * @param resolutionMm the map's point spacing (its {@code Resolution:}), mm; maps Mapper3 built
 *     from laser logs use 20
 * @param minRangeMm readings closer than this are the robot itself or noise, mm
 * @param matchRangeMm readings up to this range are used to match scans, mm
 * @param mapRangeMm readings up to this range become map points, mm (far readings carry more of a
 *     heading error into the map)
 * @param nodeSpacingMm a scan becomes a pose of the graph once the robot moved this far from the
 *     last one, mm
 * @param nodeTurnDeg ... or turned this much, degrees
 * @param localWindowMm scans matched against the map of the last this many mm of travel, mm
 * @param loopSearchMm a loop closure is looked for within this distance of the estimated pose, mm,
 *     plus {@code loopSearchPerMetre} per metre driven since the place was last seen
 * @param loopSearchPerMetre growth of the loop search radius with the distance driven, mm per m
 * @param loopMinTravelMm a place counts as revisited only after this much driving, mm
 * @param pruneRedundant whether the scan of a pose close to an older one (same place, same heading)
 *     is let go once it leaves the local window (its map points are kept, as cells in the older
 *     pose's frame), so memory grows with the area mapped, not the log's length
 */
public record MapBuilderParams(
    int resolutionMm,
    double minRangeMm,
    double matchRangeMm,
    double mapRangeMm,
    double nodeSpacingMm,
    double nodeTurnDeg,
    double localWindowMm,
    double loopSearchMm,
    double loopSearchPerMetre,
    double loopMinTravelMm,
    boolean pruneRedundant) {

  /** The defaults. */
  public static final MapBuilderParams DEFAULTS =
      new MapBuilderParams(20, 100, 20000, 12000, 100, 5, 12000, 1500, 40, 15000, true);

  /** Checks the values. */
  public MapBuilderParams {
    if (resolutionMm < 1 || resolutionMm > 1000) {
      throw new IllegalArgumentException("the map resolution is 1..1000 mm, not " + resolutionMm);
    }
    if (!(minRangeMm >= 0 && minRangeMm < mapRangeMm && mapRangeMm <= matchRangeMm)) {
      throw new IllegalArgumentException(
          "ranges must satisfy 0 <= min < map <= match: "
              + minRangeMm
              + ", "
              + mapRangeMm
              + ", "
              + matchRangeMm);
    }
    if (!(nodeSpacingMm > 0 && nodeTurnDeg > 0 && localWindowMm > 0 && loopSearchMm > 0)) {
      throw new IllegalArgumentException("spacings, window and search radius must be positive");
    }
  }

  /** These parameters with another resolution. */
  public MapBuilderParams withResolution(int mm) {
    return new MapBuilderParams(
        mm,
        minRangeMm,
        matchRangeMm,
        mapRangeMm,
        nodeSpacingMm,
        nodeTurnDeg,
        localWindowMm,
        loopSearchMm,
        loopSearchPerMetre,
        loopMinTravelMm,
        pruneRedundant);
  }

  /** These parameters with another range for map points (and matching, if that is shorter). */
  public MapBuilderParams withMapRange(double mm) {
    return new MapBuilderParams(
        resolutionMm,
        minRangeMm,
        Math.max(matchRangeMm, mm),
        mm,
        nodeSpacingMm,
        nodeTurnDeg,
        localWindowMm,
        loopSearchMm,
        loopSearchPerMetre,
        loopMinTravelMm,
        pruneRedundant);
  }
}
