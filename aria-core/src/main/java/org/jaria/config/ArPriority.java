package org.jaria.config;

/**
 * How important a configuration parameter is to the people editing it (ARIA's {@code
 * ArPriority::Priority}): editors show {@link #IMPORTANT} ones first and may hide {@link #EXPERT}
 * and lower ones. It does not change how a parameter behaves.
 */
public enum ArPriority {
  /** Every user should look at it. */
  IMPORTANT,
  /** An ordinary setting. */
  NORMAL,
  /** A detail most users leave alone. */
  DETAILED,
  /** Only for people who know the algorithm. */
  EXPERT,
  /** Set once for the hardware. */
  FACTORY,
  /** Set by calibration procedures. */
  CALIBRATION
}
