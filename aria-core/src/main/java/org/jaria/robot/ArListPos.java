package org.jaria.robot;

/** Where in a list to add something (ARIA's {@code ArListPos}). */
public enum ArListPos {
  /** At the front: asked or run before everything already there. */
  FIRST,
  /** At the back. */
  LAST
}
