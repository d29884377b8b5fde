package org.jaria.arnl;

/** What the localization task is doing (ARNL's {@code LocalizationState}). */
public enum LocalizationState {
  /** No initial pose yet: call a localizeRobot… method. */
  NOT_INITIALIZED,
  /** The last update failed: too few echoes matched the map. */
  LOCALIZATION_FAILED,
  /** The last update passed. */
  LOCALIZATION_SUCCESS,
  /** Looking for the robot (global localization, or localizing at home). */
  LOCALIZATION_INIT_COMPUTING,
  /** Updates are switched off ({@link ArSonarLocalizationTask#setIdleFlag}). */
  LOCALIZATION_IDLE
}
