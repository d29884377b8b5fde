package org.jaria.acts.blob;

import java.util.Arrays;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.color.LookupTables;
import org.jaria.acts.color.MaskRuns;

/**
 * Finds the blobs of every channel in a frame, the CMVision way ACTS works:
 *
 * <ol>
 *   <li>classify each pixel for all channels at once and run-length encode each row ({@link
 *       LookupTables#encodeRuns}, one pass over the pixels);
 *   <li>for each channel that saw a pixel, take the runs containing its bit (joining runs that
 *       touch end to start) and merge runs that overlap a run of the row above with union-find,
 *       which gives 4-connected regions, exactly like CMVision;
 *   <li>accumulate each region's area, centre of gravity and bounding box;
 *   <li>optionally merge nearby regions of the channel ({@link TrackerSettings#densityMerge()});
 *   <li>drop regions smaller than the minimum size and keep the channel's tracked-blob count of the
 *       largest, largest first (ties: the region met first in raster order).
 * </ol>
 *
 * <p>Everything works on primitive arrays that belong to the tracker and are reused from frame to
 * frame; they grow when a frame needs more (noise can make one run per pixel), so no frame is ever
 * truncated, and once grown nothing is allocated per frame. A tracker is not thread-safe: use one
 * per processing thread.
 */
public final class BlobTracker {

  /** How many of a channel's largest regions density merging considers (bounds its work). */
  public static final int MERGE_CANDIDATES = 64;

  private static final int MAX = ChannelBank.MAX_TRACKED_BLOBS;

  private final MaskRuns runs = new MaskRuns();
  private final ChannelComponents comps = new ChannelComponents();

  // Each channel's own runs (mask runs containing its bit, touching ones joined), by row.
  private final int[][] chX0 = new int[ChannelBank.NUM_CHANNELS][];
  private final int[][] chX1 = new int[ChannelBank.NUM_CHANNELS][];
  private final int[][] chRow = new int[ChannelBank.NUM_CHANNELS][];
  private final int[] chCount = new int[ChannelBank.NUM_CHANNELS];

  // The channel being labelled: its runs, union-find parents and component labels.
  private int[] cx0;
  private int[] cx1;
  private int[] crow;
  private int nRuns;
  private int[] parent = new int[1024];
  private int[] label = new int[1024];

  // Top-N selection and merge candidates.
  private final int[] top = new int[MAX];
  private final int[] candidate = new int[MERGE_CANDIDATES];
  private final int[] mArea = new int[MERGE_CANDIDATES];
  private final long[] mSumX = new long[MERGE_CANDIDATES];
  private final long[] mSumY = new long[MERGE_CANDIDATES];
  private final int[] mLeft = new int[MERGE_CANDIDATES];
  private final int[] mRight = new int[MERGE_CANDIDATES];
  private final int[] mTop = new int[MERGE_CANDIDATES];
  private final int[] mBottom = new int[MERGE_CANDIDATES];
  private final int[] mFirst = new int[MERGE_CANDIDATES];

  /** A tracker with empty buffers. */
  public BlobTracker() {}

  /** The run-length encoding of the last frame (valid until the next call). */
  public MaskRuns runs() {
    return runs;
  }

  /**
   * Finds the blobs of every active channel.
   *
   * @param rgb packed {@code 0xRRGGBB} pixels, row by row
   * @param width frame width
   * @param height frame height
   * @param tables the compiled channels (and their tracked-blob counts)
   * @param settings minimum size and merging
   * @param out receives the blobs (previous contents are replaced)
   */
  public void track(
      int[] rgb,
      int width,
      int height,
      LookupTables tables,
      TrackerSettings settings,
      BlobFrame out) {
    long t0 = System.nanoTime();
    tables.encodeRuns(rgb, width, height, runs);
    out.clear(width, height);
    int todo = runs.seenMask() & tables.activeMask();
    distribute(todo);
    while (todo != 0) {
      int c = Integer.numberOfTrailingZeros(todo);
      todo &= todo - 1;
      labelChannel(c);
      collect(null, width);
      select(c, tables.trackedBlobs(c + 1), settings, out);
    }
    out.processNanos = System.nanoTime() - t0;
  }

  /**
   * Every 4-connected region of one channel, unfiltered (no minimum size, no merging, no limit on
   * the count), and optionally the label image.
   *
   * @param labels if not null, receives {@code width * height} labels: 0 for pixels outside the
   *     channel, {@code i + 1} for pixels of component {@code i}
   */
  public void components(
      int[] rgb,
      int width,
      int height,
      LookupTables tables,
      int channel,
      ChannelComponents out,
      int[] labels) {
    int c = ChannelBank.checkChannel(channel) - 1;
    tables.encodeRuns(rgb, width, height, runs);
    distribute(1 << c);
    labelChannel(c);
    collect(labels, width);
    out.ensure(comps.count);
    out.count = comps.count;
    System.arraycopy(comps.area, 0, out.area, 0, comps.count);
    System.arraycopy(comps.sumX, 0, out.sumX, 0, comps.count);
    System.arraycopy(comps.sumY, 0, out.sumY, 0, comps.count);
    System.arraycopy(comps.left, 0, out.left, 0, comps.count);
    System.arraycopy(comps.right, 0, out.right, 0, comps.count);
    System.arraycopy(comps.top, 0, out.top, 0, comps.count);
    System.arraycopy(comps.bottom, 0, out.bottom, 0, comps.count);
  }

  // ---------------------------------------------------------------- union-find over runs

  /**
   * Gives every channel in {@code channels} its own run list in one pass over the mask runs: a mask
   * run goes to each channel whose bit it has, so the work is the number of (run, channel) pairs
   * rather than runs times channels. Runs of different masks that touch become one run of a channel
   * they share.
   */
  private void distribute(int channels) {
    MaskRuns r = runs;
    int h = r.height();
    for (int todo = channels; todo != 0; todo &= todo - 1) {
      int c = Integer.numberOfTrailingZeros(todo);
      if (chX0[c] == null) {
        chX0[c] = new int[256];
        chX1[c] = new int[256];
        chRow[c] = new int[h + 1];
      } else if (chRow[c].length < h + 1) {
        chRow[c] = new int[h + 1];
      }
      chCount[c] = 0;
    }
    for (int y = 0; y < h; y++) {
      for (int todo = channels; todo != 0; todo &= todo - 1) {
        int c = Integer.numberOfTrailingZeros(todo);
        chRow[c][y] = chCount[c];
      }
      for (int i = r.rowStart(y), e = r.rowStart(y + 1); i < e; i++) {
        int a = r.x0(i);
        int b = r.x1(i);
        for (int m = r.mask(i) & channels; m != 0; m &= m - 1) {
          int c = Integer.numberOfTrailingZeros(m);
          int n = chCount[c];
          int[] x1 = chX1[c];
          if (n > chRow[c][y] && x1[n - 1] + 1 == a) {
            x1[n - 1] = b;
          } else {
            if (n == x1.length) {
              grow(c);
              x1 = chX1[c];
            }
            chX0[c][n] = a;
            x1[n] = b;
            chCount[c] = n + 1;
          }
        }
      }
    }
    for (int todo = channels; todo != 0; todo &= todo - 1) {
      int c = Integer.numberOfTrailingZeros(todo);
      chRow[c][h] = chCount[c];
    }
  }

  private void grow(int c) {
    int cap = chX0[c].length * 2;
    chX0[c] = Arrays.copyOf(chX0[c], cap);
    chX1[c] = Arrays.copyOf(chX1[c], cap);
  }

  /** Links the channel's runs that overlap a run of the row above (union-find). */
  private void labelChannel(int c) {
    int h = runs.height();
    int n = chCount[c];
    cx0 = chX0[c];
    cx1 = chX1[c];
    crow = chRow[c];
    nRuns = n;
    if (parent.length < n) {
      int cap = Math.max(n, parent.length * 2);
      parent = new int[cap];
      label = new int[cap];
    }
    int[] x0 = cx0;
    int[] x1 = cx1;
    int[] p = parent;
    for (int k = 0; k < n; k++) {
      p[k] = k;
    }
    for (int y = 1; y < h; y++) {
      int i = crow[y - 1];
      int ie = crow[y];
      int j = ie;
      int je = crow[y + 1];
      while (i < ie && j < je) {
        if (x1[i] < x0[j]) {
          i++;
        } else if (x1[j] < x0[i]) {
          j++;
        } else {
          union(p, i, j);
          if (x1[i] < x1[j]) {
            i++;
          } else {
            j++;
          }
        }
      }
    }
  }

  // Roots always have the smallest index of their set, so parent[k] <= k everywhere.
  private static void union(int[] p, int a, int b) {
    int ra = find(p, a);
    int rb = find(p, b);
    if (ra < rb) {
      p[rb] = ra;
    } else if (rb < ra) {
      p[ra] = rb;
    }
  }

  private static int find(int[] p, int x) {
    while (p[x] != x) {
      p[x] = p[p[x]];
      x = p[x];
    }
    return x;
  }

  /** Flattens the sets, numbers the components in raster order and accumulates their stats. */
  private void collect(int[] labels, int width) {
    int n = nRuns;
    ChannelComponents s = comps;
    s.ensure(n);
    int[] p = parent;
    int[] lab = label;
    int[] x0 = cx0;
    int[] x1 = cx1;
    int[] area = s.area;
    long[] sumX = s.sumX;
    long[] sumY = s.sumY;
    int[] left = s.left;
    int[] right = s.right;
    int[] top = s.top;
    int[] bottom = s.bottom;
    if (labels != null) {
      Arrays.fill(labels, 0, Math.min(labels.length, width * runs.height()), 0);
    }
    int nc = 0;
    int h = runs.height();
    for (int y = 0; y < h; y++) {
      for (int k = crow[y], e = crow[y + 1]; k < e; k++) {
        int root = p[k];
        int c;
        if (root == k) {
          c = nc++;
          area[c] = 0;
          sumX[c] = 0;
          sumY[c] = 0;
          left[c] = x0[k];
          right[c] = x1[k];
          top[c] = y;
        } else {
          root = p[root]; // p[root] is final: root < k was flattened earlier in this loop
          p[k] = root;
          c = lab[root];
          left[c] = Math.min(left[c], x0[k]);
          right[c] = Math.max(right[c], x1[k]);
        }
        lab[k] = c;
        bottom[c] = y;
        int len = x1[k] - x0[k] + 1;
        area[c] += len;
        sumX[c] += (long) (x0[k] + x1[k]) * len / 2;
        sumY[c] += (long) y * len;
        if (labels != null) {
          Arrays.fill(labels, y * width + x0[k], y * width + x1[k] + 1, c + 1);
        }
      }
    }
    s.count = nc;
  }

  // ---------------------------------------------------------------- reporting

  private void select(int c, int wanted, TrackerSettings settings, BlobFrame out) {
    int n = Math.min(wanted, MAX);
    ChannelComponents s = comps;
    int min = settings.minBlobSize();
    if (settings.densityMerge()) {
      int m = mergeCandidates(settings);
      int k = 0;
      for (int i = 0; i < m; i++) {
        if (mRight[i] - mLeft[i] + 1 >= min && mBottom[i] - mTop[i] + 1 >= min) {
          k = insert(top, k, n, i, mArea, mFirst);
        }
      }
      for (int i = 0; i < k; i++) {
        int j = top[i];
        out.set(c, i, mArea[j], mSumX[j], mSumY[j], mLeft[j], mRight[j], mTop[j], mBottom[j]);
      }
      out.count[c] = k;
      return;
    }
    int k = 0;
    for (int i = 0; i < s.count; i++) {
      if (s.right[i] - s.left[i] + 1 >= min && s.bottom[i] - s.top[i] + 1 >= min) {
        k = insert(top, k, n, i, s.area, null);
      }
    }
    for (int i = 0; i < k; i++) {
      int j = top[i];
      out.set(c, i, s.area[j], s.sumX[j], s.sumY[j], s.left[j], s.right[j], s.top[j], s.bottom[j]);
    }
    out.count[c] = k;
  }

  /**
   * Inserts item {@code i} into {@code list[0..k)} kept sorted by area, largest first, holding at
   * most {@code n}; ties keep the item with the smaller {@code order} (or index) first.
   *
   * @return the new length
   */
  private static int insert(int[] list, int k, int n, int i, int[] area, int[] order) {
    int a = area[i];
    int pos = k;
    while (pos > 0 && precedes(a, order == null ? i : order[i], list[pos - 1], area, order)) {
      pos--;
    }
    if (pos >= n) {
      return k;
    }
    int end = Math.min(k, n - 1);
    System.arraycopy(list, pos, list, pos + 1, end - pos);
    list[pos] = i;
    return Math.min(k + 1, n);
  }

  private static boolean precedes(int a, int ord, int other, int[] area, int[] order) {
    int b = area[other];
    return a > b || (a == b && ord < (order == null ? other : order[other]));
  }

  /**
   * Copies the channel's largest regions into the merge arrays and merges pairs that are close and
   * dense enough until none is left.
   *
   * @return the number of merged regions
   */
  private int mergeCandidates(TrackerSettings settings) {
    ChannelComponents s = comps;
    int k = 0;
    for (int i = 0; i < s.count; i++) {
      k = insert(candidate, k, MERGE_CANDIDATES, i, s.area, null);
    }
    for (int i = 0; i < k; i++) {
      int j = candidate[i];
      mArea[i] = s.area[j];
      mSumX[i] = s.sumX[j];
      mSumY[i] = s.sumY[j];
      mLeft[i] = s.left[j];
      mRight[i] = s.right[j];
      mTop[i] = s.top[j];
      mBottom[i] = s.bottom[j];
      mFirst[i] = j;
    }
    int gap = settings.mergeGap();
    double density = settings.mergeDensity();
    boolean merged = true;
    while (merged) {
      merged = false;
      for (int i = 0; i < k && !merged; i++) {
        for (int j = i + 1; j < k && !merged; j++) {
          int l = Math.min(mLeft[i], mLeft[j]);
          int r = Math.max(mRight[i], mRight[j]);
          int t = Math.min(mTop[i], mTop[j]);
          int b = Math.max(mBottom[i], mBottom[j]);
          int gapX = Math.max(mLeft[i], mLeft[j]) - Math.min(mRight[i], mRight[j]) - 1;
          int gapY = Math.max(mTop[i], mTop[j]) - Math.min(mBottom[i], mBottom[j]) - 1;
          long box = (long) (r - l + 1) * (b - t + 1);
          if (gapX <= gap && gapY <= gap && mArea[i] + mArea[j] >= density * box) {
            mArea[i] += mArea[j];
            mSumX[i] += mSumX[j];
            mSumY[i] += mSumY[j];
            mLeft[i] = l;
            mRight[i] = r;
            mTop[i] = t;
            mBottom[i] = b;
            mFirst[i] = Math.min(mFirst[i], mFirst[j]);
            k--;
            copyMerge(k, j);
            merged = true;
          }
        }
      }
    }
    return k;
  }

  private void copyMerge(int from, int to) {
    mArea[to] = mArea[from];
    mSumX[to] = mSumX[from];
    mSumY[to] = mSumY[from];
    mLeft[to] = mLeft[from];
    mRight[to] = mRight[from];
    mTop[to] = mTop[from];
    mBottom[to] = mBottom[from];
    mFirst[to] = mFirst[from];
  }
}
