package org.jaria.laser;

/**
 * ARIA's older name for the SICK LMS-200 driver ({@code ArSick}), kept so programs written against
 * it (such as the thesis's) read the same; it is an {@link ArLMS2xx}.
 */
public class ArSick extends ArLMS2xx {

  /** An LMS-200 with ARIA's default settings. */
  public ArSick() {
    super();
  }

  /** An LMS-200 set up as {@code settings} says. */
  public ArSick(String name, LmsSettings settings) {
    super(name, settings);
  }
}
