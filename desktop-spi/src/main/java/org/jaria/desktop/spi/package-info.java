/**
 * How the {@code jaria} command line finds the desktop apps: the service interface {@link
 * org.jaria.desktop.spi.DesktopApps}, which the apps implement and the command line looks up with
 * {@link java.util.ServiceLoader}. Neither side needs the other to be built.
 */
package org.jaria.desktop.spi;
