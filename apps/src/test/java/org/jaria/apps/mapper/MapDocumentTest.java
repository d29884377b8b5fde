package org.jaria.apps.mapper;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.BitSet;
import java.util.List;
import java.util.Set;
import org.jaria.geom.ArLineSegment;
import org.jaria.map.ArMapObject;
import org.junit.jupiter.api.Test;

class MapDocumentTest {

  private static final Path FILE = Path.of("x.map");

  @Test
  void undoRedoRestoreExactContentAndNames() {
    MapDocument d = MapDocument.newMap();
    MapContent empty = d.content();
    d.execute(MapEdits.addLine(new ArLineSegment(0, 0, 1000, 0)));
    d.execute(MapEdits.addObject(ArMapObject.goal("A", 10, 20)));
    MapContent two = d.content();
    assertEquals("Add goal", d.undoName());
    assertTrue(d.undo());
    assertEquals("Add goal", d.redoName());
    assertEquals(1, d.content().lines().size());
    assertTrue(d.content().objects().isEmpty());
    assertTrue(d.undo());
    assertSame(empty, d.content());
    assertFalse(d.undo());
    assertTrue(d.redo());
    assertTrue(d.redo());
    assertSame(two, d.content());
    assertFalse(d.redo());
  }

  @Test
  void newEditClearsRedo() {
    MapDocument d = MapDocument.newMap();
    d.execute(MapEdits.addObject(ArMapObject.goal("A", 0, 0)));
    d.undo();
    d.execute(MapEdits.addObject(ArMapObject.goal("B", 0, 0)));
    assertFalse(d.canRedo());
    assertEquals("B", d.content().objects().get(0).object().name());
  }

  @Test
  void editThatChangesNothingIsNotRecorded() {
    MapDocument d = MapDocument.newMap();
    d.execute(MapEdits.delete(Set.of(), new BitSet()));
    assertFalse(d.canUndo());
    assertFalse(d.isModified());
  }

  @Test
  void modifiedFollowsTheSavedStateThroughUndoAndRedo() {
    MapDocument d = MapDocument.newMap();
    assertFalse(d.isModified());
    d.execute(MapEdits.addObject(ArMapObject.goal("A", 0, 0)));
    assertTrue(d.isModified());
    d.markSaved(d.saveMark(), FILE);
    assertFalse(d.isModified());
    assertEquals("x.map", d.title());
    d.execute(MapEdits.addObject(ArMapObject.goal("B", 0, 0)));
    assertTrue(d.isModified());
    d.undo();
    assertFalse(d.isModified());
    d.undo();
    assertTrue(d.isModified());
    d.redo();
    assertFalse(d.isModified());
  }

  @Test
  void savedStateOverwrittenAfterUndoStaysModified() {
    MapDocument d = MapDocument.newMap();
    d.execute(MapEdits.addObject(ArMapObject.goal("A", 0, 0)));
    d.markSaved(d.saveMark(), FILE);
    d.undo();
    d.execute(MapEdits.addObject(ArMapObject.goal("B", 0, 0)));
    assertTrue(d.isModified());
    d.undo();
    assertTrue(d.isModified(), "the saved state (with A) can no longer be reached");
  }

  @Test
  void saveStartedBeforeMoreEditsMarksTheRightState() {
    MapDocument d = MapDocument.newMap();
    d.execute(MapEdits.addObject(ArMapObject.goal("A", 0, 0)));
    long mark = d.saveMark();
    d.execute(MapEdits.addObject(ArMapObject.goal("B", 0, 0)));
    d.markSaved(mark, FILE); // the background save finished after B was added
    assertTrue(d.isModified());
    d.undo();
    assertFalse(d.isModified());
  }

  @Test
  void historyIsBoundedAndForgottenStatesAreModified() {
    MapDocument d = MapDocument.newMap();
    for (int i = 0; i < MapDocument.UNDO_LIMIT + 5; i++) {
      d.execute(MapEdits.addObject(ArMapObject.goal("G" + i, i, 0)));
    }
    int undone = 0;
    while (d.undo()) {
      undone++;
    }
    assertEquals(MapDocument.UNDO_LIMIT, undone);
    assertEquals(5, d.content().objects().size());
    assertTrue(d.isModified(), "the empty, saved state is out of reach");
  }

  @Test
  void replaceOfMissingObjectFails() {
    MapDocument d = MapDocument.newMap();
    assertThrows(
        IllegalArgumentException.class,
        () -> d.execute(MapEdits.replace("Rename", 42, ArMapObject.goal("x", 0, 0))));
  }

  @Test
  void listenersHearEveryChange() {
    MapDocument d = MapDocument.newMap();
    int[] calls = {0};
    d.addListener(() -> calls[0]++);
    d.execute(MapEdits.addPoints(new int[] {1, 2}, new int[] {3, 4}));
    d.undo();
    d.redo();
    d.markSaved(d.saveMark(), FILE);
    assertEquals(4, calls[0]);
    assertEquals(List.of(1, 2), List.of(d.content().points().x(0), d.content().points().x(1)));
  }
}
