/**
 * Drivers for real laser range finders: the SICK LMS-200 family ({@link org.jaria.laser.ArLMS2xx},
 * alias {@link org.jaria.laser.ArSick}) over its binary telegrams, and the Hokuyo URG ({@link
 * org.jaria.laser.ArUrg}) over SCIP 2.0 text lines, each a range device and a laser scan source,
 * plus {@link org.jaria.laser.ArLaserConnector}, which builds them from ARIA's command-line options
 * and robot parameter keys. The byte layouts live in small codec classes ({@code LmsTelegram},
 * {@code LmsScanData}, {@code Scip}) that are plain functions over bytes, tested against golden
 * vectors.
 */
package org.jaria.laser;
