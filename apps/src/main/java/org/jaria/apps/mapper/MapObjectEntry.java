package org.jaria.apps.mapper;

import org.jaria.map.ArMapObject;

/**
 * A map object (goal, home, dock, forbidden line or area...) of the map being edited, with the
 * editor's number for it.
 *
 * @param id the editor's number, unique within a document
 * @param object the object
 */
public record MapObjectEntry(long id, ArMapObject object) {}
