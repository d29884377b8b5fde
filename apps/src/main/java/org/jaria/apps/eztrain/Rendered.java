package org.jaria.apps.eztrain;

import java.util.List;
import org.jaria.acts.blob.Blob;
import org.jaria.acts.image.RgbImage;

/**
 * One refresh of the training window: the frame, what the view shows of it, the selected channel's
 * blobs and colour planes, and how long tracking took.
 *
 * @param frame the frame that was tracked
 * @param viewArgb the training image in the view mode, ARGB, the frame's size
 * @param channel the channel shown
 * @param mode the view mode
 * @param blobs the channel's tracked blobs, largest first
 * @param trackNanos time to classify and track the frame (all channels)
 * @param planes the channel's RG, BG and RB planes as ARGB images, or null
 * @param planeSize cells per side of a plane image
 */
// The arrays are handed from the view thread to the JavaFX thread and not changed afterwards.
@SuppressWarnings("ArrayRecordComponent")
public record Rendered(
    RgbImage frame,
    int[] viewArgb,
    int channel,
    ViewMode mode,
    List<Blob> blobs,
    long trackNanos,
    int[][] planes,
    int planeSize) {}
