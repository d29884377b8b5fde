package org.jaria.apps.mapper;

import org.jaria.geom.ArLineSegment;

/**
 * A wall line of the map being edited, with the editor's number for it (so selection and undo can
 * refer to it while other lines come and go).
 *
 * @param id the editor's number, unique within a document
 * @param segment the line, mm
 */
public record MapLine(long id, ArLineSegment segment) {}
