/**
 * What the network server asks of the rest of the robot program: small interfaces over
 * localization, path planning, configuration and a camera, so the server and its services work with
 * any implementation. {@link org.jaria.net.provider.ArConfigRegistry} serves an {@code ArConfig};
 * {@code org.jaria.net.arnl} (module arnl-net) adapts SonARNL. Implementations must be thread-safe:
 * the server calls them from its own threads.
 */
package org.jaria.net.provider;
