package org.jaria.acts.blob;

/**
 * How the {@link BlobTracker} turns connected regions into reported blobs.
 *
 * @param minBlobSize a blob is reported only if its bounding box is at least this many pixels wide
 *     and tall (ACTS.pref's "minimum run length and width", default 5; 1 reports everything)
 * @param densityMerge whether nearby blobs of the same channel are merged (see below)
 * @param mergeGap merge only blobs whose bounding boxes are at most this many pixels apart
 *     horizontally and vertically (0 = touching or overlapping boxes)
 * @param mergeDensity merge only if the merged blob fills at least this fraction (0..1) of its
 *     merged bounding box, so two small blobs far apart in a large empty box stay separate
 */
public record TrackerSettings(
    int minBlobSize, boolean densityMerge, int mergeGap, double mergeDensity) {

  /** ACTS's defaults: minimum size 5, no merging. */
  public static final TrackerSettings DEFAULT = new TrackerSettings(5, false, 4, 0.4);

  /** Every region is a blob (minimum size 1), no merging: what a reference labelling gives. */
  public static final TrackerSettings ALL_REGIONS = new TrackerSettings(1, false, 4, 0.4);

  /** Checks the ranges. */
  public TrackerSettings {
    if (minBlobSize < 1 || minBlobSize > 4095) {
      throw new IllegalArgumentException("minimum blob size must be 1..4095, got " + minBlobSize);
    }
    if (mergeGap < 0 || mergeGap > 4095) {
      throw new IllegalArgumentException("merge gap must be 0..4095 pixels, got " + mergeGap);
    }
    if (!(mergeDensity >= 0 && mergeDensity <= 1)) {
      throw new IllegalArgumentException("merge density must be 0..1, got " + mergeDensity);
    }
  }

  /** These settings with another minimum blob size. */
  public TrackerSettings withMinBlobSize(int size) {
    return new TrackerSettings(size, densityMerge, mergeGap, mergeDensity);
  }

  /** These settings with density merging on, using the given gap and density. */
  public TrackerSettings withDensityMerge(int gap, double density) {
    return new TrackerSettings(minBlobSize, true, gap, density);
  }
}
