package org.jaria.mapping;

import org.jaria.geom.ArPose;

/** Rigid-motion arithmetic on poses (mm, degrees). */
final class Poses {

  private Poses() {}

  /** {@code a} then {@code b} in a's frame. */
  static ArPose compose(ArPose a, ArPose b) {
    double c = Math.cos(a.getThRad());
    double s = Math.sin(a.getThRad());
    return new ArPose(
        a.x() + c * b.x() - s * b.y(), a.y() + s * b.x() + c * b.y(), a.th() + b.th());
  }

  /** The pose that undoes {@code a}. */
  static ArPose inverse(ArPose a) {
    double c = Math.cos(a.getThRad());
    double s = Math.sin(a.getThRad());
    return new ArPose(-c * a.x() - s * a.y(), s * a.x() - c * a.y(), -a.th());
  }

  /** {@code b} seen from {@code a}. */
  static ArPose between(ArPose a, ArPose b) {
    return compose(inverse(a), b);
  }
}
