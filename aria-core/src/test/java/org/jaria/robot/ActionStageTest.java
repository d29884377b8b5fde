package org.jaria.robot;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.jaria.action.ArAction;
import org.jaria.action.ArActionDesired;
import org.jaria.action.ArResolver;
import org.junit.jupiter.api.Test;

/**
 * The action list a cycle reads is one immutable snapshot: a change made while a cycle runs (from
 * any thread) is published whole, for the next cycle, and never changes the list under the
 * resolver's feet. (The list used to be one shared list that {@code add} emptied and refilled, so a
 * cycle could find it half made or empty.)
 */
class ActionStageTest {

  private static ArAction action(String name) {
    return new ArAction(name) {
      @Override
      public ArActionDesired fire(ArActionDesired currentDesired) {
        return null;
      }
    };
  }

  private static List<String> names(List<ArResolver.PrioritizedAction> list) {
    List<String> out = new ArrayList<>();
    for (ArResolver.PrioritizedAction p : list) {
      out.add(p.action().getName());
    }
    return out;
  }

  /** A resolver that records what the cycle handed it, before and after {@code duringCycle}. */
  private static final class Watching implements ArResolver {
    final List<List<String>> seenAtStart = new ArrayList<>();
    final List<List<String>> seenAtEnd = new ArrayList<>();
    final List<List<ArResolver.PrioritizedAction>> handed = new ArrayList<>();
    Runnable duringCycle = () -> {};

    @Override
    public ArActionDesired resolve(List<PrioritizedAction> actions, ArRobot robot) {
      handed.add(actions);
      seenAtStart.add(names(actions));
      duringCycle.run();
      seenAtEnd.add(names(actions));
      return new ArActionDesired();
    }
  }

  @Test
  void aChangeDuringACycleLeavesThatCyclesListAsItWasAndShowsInTheNext() throws Exception {
    ActionStage stage = new ActionStage();
    ArAction a = action("a");
    ArAction b = action("b");
    stage.add(a, 10);
    Watching resolver = new Watching();
    stage.setResolver(resolver);
    // Another thread raises a's priority and adds b while the cycle is resolving.
    resolver.duringCycle =
        () -> {
          Thread other =
              new Thread(
                  () -> {
                    stage.add(b, 20);
                    stage.add(a, 30);
                  },
                  "ActionStageTest-changer");
          other.start();
          try {
            other.join();
          } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
          }
        };
    stage.resolve(null, true);
    resolver.duringCycle = () -> {};
    stage.resolve(null, true);

    assertEquals(List.of(List.of("a"), List.of("a", "b")), resolver.seenAtStart);
    assertEquals(
        List.of(List.of("a"), List.of("a", "b")),
        resolver.seenAtEnd,
        "the list a cycle resolves does not change while it resolves");
  }

  @Test
  void theCycleIsHandedAListNobodyCanChange() {
    ActionStage stage = new ActionStage();
    stage.add(action("a"), 10);
    Watching resolver = new Watching();
    stage.setResolver(resolver);
    stage.resolve(null, true);
    List<ArResolver.PrioritizedAction> handed = resolver.handed.get(0);
    assertThrows(
        UnsupportedOperationException.class,
        () -> handed.add(new ArResolver.PrioritizedAction(1, action("x"))));
    assertThrows(UnsupportedOperationException.class, handed::clear);
    // and the program's view is the same snapshot, not a live list
    assertSame(stage.list(), handed);
  }

  @Test
  void eachChangePublishesOneCompleteSortedList() {
    ActionStage stage = new ActionStage();
    ArAction a = action("a");
    ArAction b = action("b");
    ArAction c = action("c");
    stage.add(a, 10);
    List<ArResolver.PrioritizedAction> one = stage.list();
    stage.add(b, 50);
    stage.add(c, 10); // equal priorities keep the order they were added in
    List<ArResolver.PrioritizedAction> three = stage.list();
    stage.add(a, 90); // a new priority moves it, and it is not there twice
    assertEquals(List.of("a"), names(one), "an earlier snapshot never changes");
    assertEquals(List.of("b", "a", "c"), names(three));
    assertEquals(List.of("a", "b", "c"), names(stage.list()));
    assertTrue(stage.remove(b));
    assertFalse(stage.remove(b));
    assertEquals(List.of("a", "c"), names(stage.list()));
    assertSame(c, stage.find("c"));
    assertNull(stage.find("b"));
  }

  @Test
  void withoutActionsOrConnectionTheResolverIsNotAsked() {
    ActionStage stage = new ActionStage();
    Watching resolver = new Watching();
    stage.setResolver(resolver);
    stage.resolve(null, true);
    stage.add(action("a"), 10);
    stage.resolve(null, false);
    assertTrue(resolver.handed.isEmpty());
  }
}
