/**
 * Maps in ARIA's {@code .map} format: {@link org.jaria.map.ArMap} (the document: wall lines, sensor
 * points, goals, home, forbidden lines and areas), {@link org.jaria.map.ArMapObject} (one {@code
 * Cairn:} object), {@link org.jaria.map.ArMapPoints} (the points as primitive arrays) and {@link
 * org.jaria.map.MapInfoEntry}. Maps written by ARIA's tools (Mapper3, MobileSim) load unchanged,
 * and unedited maps are written back byte for byte. Two example maps ship with JAria: {@code
 * ArMap.loadBundled("office")} and {@code ArMap.loadBundled("hall")}.
 */
package org.jaria.map;
