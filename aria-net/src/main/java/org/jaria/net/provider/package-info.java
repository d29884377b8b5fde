/**
 * What the network server asks of the rest of the robot program: small interfaces that adapters
 * implement over SonARNL's localization and path planning, ArConfig and a camera, so that {@code
 * aria-net} depends on {@code aria-core} only. Implementations must be thread-safe: the server
 * calls them from its own threads, never from the robot's cycle.
 */
package org.jaria.net.provider;
