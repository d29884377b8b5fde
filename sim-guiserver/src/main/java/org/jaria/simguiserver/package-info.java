/**
 * The guiServer on an embedded simulator ({@link org.jaria.simguiserver.SimulatedGuiServer}: a
 * simulated robot with SonARNL, its camera as video), and mapping while driving on a guiServer
 * ({@link org.jaria.simguiserver.ScanMapping}), for {@code jaria demo guiserver}, the monitor's
 * tests and the network benchmarks.
 */
package org.jaria.simguiserver;
