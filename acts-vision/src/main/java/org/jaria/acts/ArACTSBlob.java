package org.jaria.acts;

import java.util.Locale;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One blob as ACTS reports it (ARIA's {@code ArACTSBlob}): area in pixels, centre of gravity and
 * bounding box in image pixel coordinates (x = column from the left, y = row from the top). Filled
 * in by {@link ArACTS_1_2#getBlob(int, int, ArACTSBlob)}.
 */
public class ArACTSBlob {

  private static final Logger LOG = LoggerFactory.getLogger(ArACTSBlob.class);

  private int area;
  private int xcg;
  private int ycg;
  private int left;
  private int right;
  private int top;
  private int bottom;

  /** An all-zero blob. */
  public ArACTSBlob() {}

  /** Number of pixels covered by the blob. */
  public int getArea() {
    return area;
  }

  /** Centre of gravity, x (column). */
  public int getXCG() {
    return xcg;
  }

  /** Centre of gravity, y (row). */
  public int getYCG() {
    return ycg;
  }

  /** Left border (column). */
  public int getLeft() {
    return left;
  }

  /** Right border (column). */
  public int getRight() {
    return right;
  }

  /** Top border (row). */
  public int getTop() {
    return top;
  }

  /** Bottom border (row). */
  public int getBottom() {
    return bottom;
  }

  /** Sets the area. */
  public void setArea(int area) {
    this.area = area;
  }

  /** Sets the centre of gravity x. */
  public void setXCG(int xcg) {
    this.xcg = xcg;
  }

  /** Sets the centre of gravity y. */
  public void setYCG(int ycg) {
    this.ycg = ycg;
  }

  /** Sets the left border. */
  public void setLeft(int left) {
    this.left = left;
  }

  /** Sets the right border. */
  public void setRight(int right) {
    this.right = right;
  }

  /** Sets the top border. */
  public void setTop(int top) {
    this.top = top;
  }

  /** Sets the bottom border. */
  public void setBottom(int bottom) {
    this.bottom = bottom;
  }

  /** Logs the blob's statistics (ARIA's {@code log()}). */
  public void log() {
    LOG.info(toString());
  }

  /** The statistics in ARIA's log format. */
  @Override
  public String toString() {
    return String.format(
        Locale.ROOT,
        "Area: %3d X: %3d Y: %3d l: %3d r: %3d t: %3d: b: %3d",
        area,
        xcg,
        ycg,
        left,
        right,
        top,
        bottom);
  }

  /** Makes this blob a copy of {@code other} (to keep a blob while reusing the other). */
  public void copyFrom(ArACTSBlob other) {
    setArea(other.getArea());
    setXCG(other.getXCG());
    setYCG(other.getYCG());
    setLeft(other.getLeft());
    setRight(other.getRight());
    setTop(other.getTop());
    setBottom(other.getBottom());
  }
}
