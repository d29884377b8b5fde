package org.jaria.laser;

/** The LMS-200 telegram codes JAria uses (an answer's code is its command's plus 0x80). */
public final class LmsCommands {

  private LmsCommands() {}

  /** Reset; answered by {@link #POWER_ON}. */
  public static final int RESET = 0x10;

  /** Change the operating mode (install mode, continuous output, stop, baud rate). */
  public static final int CHANGE_MODE = 0x20;

  /** Request the status block. */
  public static final int STATUS = 0x31;

  /** Set the field of view and angular resolution. */
  public static final int VARIANT = 0x3b;

  /** Set the configuration block (measuring mode, units). */
  public static final int CONFIGURE = 0x77;

  /** The laser's power-on message. */
  public static final int POWER_ON = 0x90;

  /** The laser's "not acknowledged" answer (a telegram it could not use). */
  public static final int NOT_ACKNOWLEDGED = 0x92;

  /** Answer to {@link #CHANGE_MODE}: data byte 0 is 0 on success. */
  public static final int MODE_ANSWER = 0xa0;

  /** A scan of measured values. */
  public static final int SCAN = 0xb0;

  /** Answer to {@link #STATUS}. */
  public static final int STATUS_ANSWER = 0xb1;

  /** Answer to {@link #VARIANT}: data byte 0 is 1 on success, then width and increment. */
  public static final int VARIANT_ANSWER = 0xbb;

  /** Answer to {@link #CONFIGURE}: data byte 0 is 1 on success. */
  public static final int CONFIGURE_ANSWER = 0xf7;

  /** Mode: installation mode (needs the password "SICK_LMS"). */
  public static final int MODE_INSTALL = 0x00;

  /** Mode: send every scan continuously. */
  public static final int MODE_CONTINUOUS = 0x24;

  /** Mode: stop sending scans (send on request only). */
  public static final int MODE_STOP = 0x25;

  /** The installation-mode password every LMS-200 ships with. */
  public static final String PASSWORD = "SICK_LMS";
}
