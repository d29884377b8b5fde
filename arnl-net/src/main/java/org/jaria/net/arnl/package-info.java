/**
 * SonARNL behind the network server: {@link org.jaria.net.arnl.ArnlNavigation} sets a robot up for
 * navigation as the thesis's guiServer does, and its adapters serve the localization and the path
 * planner to monitors.
 */
package org.jaria.net.arnl;
