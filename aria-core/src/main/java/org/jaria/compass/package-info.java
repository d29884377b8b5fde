/** The TCM2 compass module ({@link org.jaria.compass.ArTCM2}). */
package org.jaria.compass;
