/**
 * Grids shared by localization and planning: {@link org.jaria.arnl.grid.GridSpec} (where a grid
 * lies), {@link org.jaria.arnl.grid.MapRaster} (drawing map lines, points and forbidden objects
 * into cells) and {@link org.jaria.arnl.grid.DistanceField} (exact Euclidean distance transform).
 */
package org.jaria.arnl.grid;
