/**
 * Assignment packs: a teacher's own assignments, in a folder or a jar of their own, graded by
 * {@code jaria grade --pack} without touching JAria. {@link org.jaria.classroom.pack.Packs} loads
 * them (compiling a folder's sources), {@link org.jaria.classroom.pack.PackTemplate} writes a
 * starter pack to begin from.
 */
package org.jaria.classroom.pack;
