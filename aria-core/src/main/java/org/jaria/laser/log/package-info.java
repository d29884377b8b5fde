/**
 * Laser scan logs ({@code .2d} files) in ARIA's text format, the files {@code sickLogger} and
 * {@link org.jaria.laser.ArLaserLogger} write and a map builder reads: {@link
 * org.jaria.laser.log.ScanLogReader} streams a log entry by entry (a whole log is never held in
 * memory), {@link org.jaria.laser.log.ScanLogWriter} writes one line for line as ARIA does. The
 * entries are values: the header ({@link org.jaria.laser.log.ScanLogHeader}), one laser scan with
 * the robot's pose ({@link org.jaria.laser.log.LoggedScan}), and a tag such as a goal placed while
 * driving ({@link org.jaria.laser.log.LogTag}).
 *
 * <p>The format, as ARIA writes it: the first line is {@code LaserOdometryLog}; lines starting with
 * {@code #} are comments; every other line is a tag, a colon and values. The header gives the
 * laser's mounting pose ({@code sick1pose: X Y TH}, {@code scan1pose: X Y Z TH}), its field of view
 * and number of readings ({@code sick1conf: FIRST LAST COUNT}) and which robot poses each scan
 * carries ({@code locationTypes: robot robotGlobal}). Each scan is a block: {@code logTime:}
 * seconds since logging started, {@code velocities:}, {@code scanId:}, {@code robot: X Y TH} (the
 * odometry pose when the readings were taken), {@code robotGlobal: X Y TH}, and last {@code scan1:}
 * with one {@code X Y} pair per reading in the laser's own frame (x ahead of the laser), {@code 0
 * 0} for a reading with no echo. A tag block is {@code time:}, the poses, then the tag's text, e.g.
 * {@code cairn: GoalWithHeading "" ICON_GOALWITHHEADING "goal1"}. Older logs carry {@code sick1:}
 * with ranges instead of {@code scan1:} pairs, and {@code time:} instead of {@code logTime:}; both
 * read.
 */
package org.jaria.laser.log;
