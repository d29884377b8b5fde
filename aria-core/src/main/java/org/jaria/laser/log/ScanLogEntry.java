package org.jaria.laser.log;

/** One entry of a laser scan log after its header: a scan or a tag. */
public sealed interface ScanLogEntry permits LoggedScan, LogTag {

  /** Seconds since logging started (as the log says; a log may go backwards). */
  double time();
}
