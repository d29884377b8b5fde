package org.jaria.sim;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Ports as MobileSim hands them out: factories from the base port on, then the robots. */
class ServerPlanTest {

  @Test
  void factoriesTakeTheFirstPortsAndRobotsTheNext() {
    ServerPlan p = new ServerPlan(8101, 2, 3);
    assertEquals(8101, p.factoryPort(0));
    assertEquals(8102, p.factoryPort(1));
    assertEquals(8103, p.robotPort(0));
    assertEquals(8105, p.robotPort(2));
    assertEquals(8101, new ServerPlan(8101, 0, 2).robotPort(0), "no factory: robots as always");
    assertEquals(0, new ServerPlan(0, 2, 2).robotPort(1), "port 0: any free port for each");
    assertThrows(IndexOutOfBoundsException.class, () -> p.factoryPort(2));
  }

  @Test
  void portsBeyondTheLastAreRefusedWithWhatToDo() {
    IllegalArgumentException e =
        assertThrows(IllegalArgumentException.class, () -> new ServerPlan(65535, 1, 1));
    assertTrue(e.getMessage().contains("lower port"), e.getMessage());
    assertThrows(IllegalArgumentException.class, () -> new ServerPlan(-1, 0, 0));
  }
}
