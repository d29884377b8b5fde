package org.jaria.acts.color;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.function.Consumer;
import org.jaria.acts.image.RgbImage;

/**
 * EZ-Train's training tools (thesis §5.3.15–16) acting on the selected channel of a {@link
 * ChannelBank}: Add and Remove a rectangle's colours, Draw and Erase with a square brush, Pick a
 * pixel's colour, per-channel Undo, Clear Training, and the manual mode's per-plane limits, Reset
 * Limits, Fill Plane and Clear Plane.
 *
 * <p>Add and Remove take each selected pixel plus a square of neighbouring values ({@link
 * #setNeighbourhood(int) neighbourhood}, default {@value #DEFAULT_NEIGHBOURHOOD} colour values each
 * way) in every plane, as ACTS does, so a few pixels train a robust channel (and removing a few
 * stray pixels can also remove related colours). Draw and Erase take the brush's exact colours, for
 * fine touch-ups.
 *
 * <p>Every tool that changes a channel first saves the channel for {@link #undo()}; each channel
 * keeps its own {@linkplain #setUndoLevels(int) undo levels} (default {@value
 * #DEFAULT_UNDO_LEVELS}). A user interface that applies many brush strokes for one mouse drag can
 * wrap them in {@link #beginGroup()} / {@link #endGroup()} so that one Undo reverts the whole drag.
 *
 * <p>A trainer is driven from one thread (a user interface thread); the bank it edits is
 * thread-safe, so a tracker may run on another thread meanwhile.
 */
public final class Trainer {

  /** Default neighbourhood half-width of Add/Remove, in colour values. */
  public static final int DEFAULT_NEIGHBOURHOOD = 4;

  /** Default number of undo levels per channel. */
  public static final int DEFAULT_UNDO_LEVELS = 10;

  /** Largest brush (9 × 9 pixels, ACTS's 81-pixel square). */
  public static final int MAX_BRUSH = 9;

  private final ChannelBank bank;
  private final List<Deque<Channel>> undo = new ArrayList<>(ChannelBank.NUM_CHANNELS);

  private int channel = 1;
  private int neighbourhood = DEFAULT_NEIGHBOURHOOD;
  private int brush = 1;
  private int undoLevels = DEFAULT_UNDO_LEVELS;
  private int groupDepth;
  private boolean groupSaved;

  /** A trainer editing {@code bank}, channel 1 selected. */
  public Trainer(ChannelBank bank) {
    this.bank = bank;
    for (int i = 0; i < ChannelBank.NUM_CHANNELS; i++) {
      undo.add(new ArrayDeque<>());
    }
  }

  /** The bank being trained. */
  public ChannelBank bank() {
    return bank;
  }

  /** Selects the channel (1..32) the tools act on. */
  public void setChannel(int channel) {
    this.channel = ChannelBank.checkChannel(channel);
  }

  /** The selected channel. */
  public int getChannel() {
    return channel;
  }

  /** Sets the Add/Remove neighbourhood half-width in colour values (0..64). */
  public void setNeighbourhood(int radius) {
    if (radius < 0 || radius > 64) {
      throw new IllegalArgumentException(
          "neighbourhood must be 0..64 colour values, got " + radius);
    }
    neighbourhood = radius;
  }

  /** The Add/Remove neighbourhood half-width. */
  public int getNeighbourhood() {
    return neighbourhood;
  }

  /** Sets the Draw/Erase brush to {@code size × size} pixels (1..9). */
  public void setBrushSize(int size) {
    if (size < 1 || size > MAX_BRUSH) {
      throw new IllegalArgumentException("brush size must be 1.." + MAX_BRUSH + ", got " + size);
    }
    brush = size;
  }

  /** The brush size. */
  public int getBrushSize() {
    return brush;
  }

  /** Sets how many undo levels each channel keeps (1..100); extra old levels are dropped. */
  public void setUndoLevels(int levels) {
    if (levels < 1 || levels > 100) {
      throw new IllegalArgumentException("undo levels must be 1..100, got " + levels);
    }
    undoLevels = levels;
    for (Deque<Channel> d : undo) {
      while (d.size() > levels) {
        d.removeLast();
      }
    }
  }

  /** How many undo steps the selected channel has. */
  public int undoDepth() {
    return undo.get(channel - 1).size();
  }

  // ---------------------------------------------------------------- image tools

  /** Add: the colours of the rectangle between two corners (inclusive, clipped to the image). */
  public void addRect(RgbImage image, int x0, int y0, int x1, int y1) {
    rect(image, x0, y0, x1, y1, neighbourhood, true);
  }

  /** Remove: takes the rectangle's colours and their neighbourhoods out of the channel. */
  public void removeRect(RgbImage image, int x0, int y0, int x1, int y1) {
    rect(image, x0, y0, x1, y1, neighbourhood, false);
  }

  /** Draw: adds the exact colours under the brush centred on {@code (x, y)}. */
  public void draw(RgbImage image, int x, int y) {
    int lo = (brush - 1) / 2;
    rect(image, x - lo, y - lo, x - lo + brush - 1, y - lo + brush - 1, 0, true);
  }

  /** Erase: removes the exact colours under the brush centred on {@code (x, y)}. */
  public void erase(RgbImage image, int x, int y) {
    int lo = (brush - 1) / 2;
    rect(image, x - lo, y - lo, x - lo + brush - 1, y - lo + brush - 1, 0, false);
  }

  /** Pick: the packed {@code 0xRRGGBB} colour of one pixel (changes nothing). */
  public int pick(RgbImage image, int x, int y) {
    return image.get(x, y);
  }

  /** Pick as text, the way EZ-Train prints it: {@code "R 200 G 30 B 25"}. */
  public static String describe(int rgb) {
    return "R " + ((rgb >>> 16) & 0xFF) + " G " + ((rgb >>> 8) & 0xFF) + " B " + (rgb & 0xFF);
  }

  private void rect(RgbImage image, int x0, int y0, int x1, int y1, int radius, boolean add) {
    int left = Math.max(0, Math.min(x0, x1));
    int right = Math.min(image.width() - 1, Math.max(x0, x1));
    int top = Math.max(0, Math.min(y0, y1));
    int bottom = Math.min(image.height() - 1, Math.max(y0, y1));
    if (left > right || top > bottom) {
      return; // entirely outside the image: nothing to train, nothing to undo
    }
    int[] px = image.pixels();
    int w = image.width();
    change(
        c -> {
          for (int y = top; y <= bottom; y++) {
            for (int x = left; x <= right; x++) {
              if (add) {
                c.addColor(px[y * w + x], radius);
              } else {
                c.removeColor(px[y * w + x], radius);
              }
            }
          }
        });
  }

  /** Adds every colour of an RGB box (see {@link Channel#addRgbBox}). */
  public void addRgbBox(int r0, int r1, int g0, int g1, int b0, int b1) {
    change(c -> c.addRgbBox(r0, r1, g0, g1, b0, b1));
  }

  // ---------------------------------------------------------------- channel tools

  /** Clear Training: empties the channel and resets its limits. */
  public void clearTraining() {
    change(Channel::clear);
  }

  /** Replaces the channel with {@code contents} (e.g. a loaded LUT file); undoable. */
  public void load(Channel contents) {
    Channel fitted =
        contents.cellBits() == bank.cellBits() ? contents : contents.resampled(bank.cellBits());
    change(c -> c.copyFrom(fitted));
  }

  /** Undo: restores the selected channel as it was before its last change. */
  public boolean undo() {
    Channel previous = undo.get(channel - 1).pollFirst();
    if (previous == null) {
      return false;
    }
    bank.edit(
        channel,
        c -> {
          c.copyFrom(previous);
          return null;
        });
    return true;
  }

  // ---------------------------------------------------------------- manual mode

  /** Sets both colour thresholds of a plane (degrees removed next to each axis, 0..90). */
  public void setColorLimits(ColorPlane plane, int first, int second) {
    change(c -> c.setLimits(plane, c.getLimits(plane).withColor(first, second)));
  }

  /** Sets the Low Bright and High Bright limits of a plane ({@code a + b}, 0..510). */
  public void setBrightLimits(ColorPlane plane, int low, int high) {
    change(c -> c.setLimits(plane, c.getLimits(plane).withBright(low, high)));
  }

  /** Sets all four limits of a plane. */
  public void setLimits(ColorPlane plane, PlaneLimits limits) {
    change(c -> c.setLimits(plane, limits));
  }

  /** The current limits of a plane of the selected channel. */
  public PlaneLimits getLimits(ColorPlane plane) {
    return bank.copyOf(channel).getLimits(plane);
  }

  /** Reset Limits: removes every plane's limits. */
  public void resetLimits() {
    change(Channel::resetLimits);
  }

  /** Fill Plane: sets every cell of a plane. */
  public void fillPlane(ColorPlane plane) {
    change(c -> c.fillPlane(plane));
  }

  /** Clear Plane: clears every cell of a plane. */
  public void clearPlane(ColorPlane plane) {
    change(c -> c.clearPlane(plane));
  }

  // ---------------------------------------------------------------- undo groups

  /** Starts a group of changes that one {@link #undo()} reverts together (may nest). */
  public void beginGroup() {
    if (groupDepth++ == 0) {
      groupSaved = false;
    }
  }

  /** Ends the group started by the matching {@link #beginGroup()}. */
  public void endGroup() {
    if (groupDepth == 0) {
      throw new IllegalStateException("endGroup() without beginGroup()");
    }
    groupDepth--;
  }

  private void change(Consumer<Channel> op) {
    bank.edit(
        channel,
        c -> {
          if (groupDepth == 0 || !groupSaved) {
            Deque<Channel> d = undo.get(channel - 1);
            d.addFirst(c.copy());
            while (d.size() > undoLevels) {
              d.removeLast();
            }
            groupSaved = groupDepth > 0;
          }
          op.accept(c);
          return null;
        });
  }
}
