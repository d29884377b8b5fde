package org.jaria.apps.monitor;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Set;
import org.jaria.net.data.InfoStrings;
import org.jaria.net.data.LocalizationSnapshot;
import org.jaria.net.data.RobotUpdate;
import org.junit.jupiter.api.Test;

/** When the monitor counts as ready: the first of each offered thing its panel shows is there. */
class MonitorStateTest {

  private static RobotUpdate update() {
    return new RobotUpdate(
        "Stop", "Stopped", 13.0, 1500, 9500, 0, 0, 0, 0, 0, true, false, false, false, 0, 1);
  }

  @Test
  void readyWaitsForEachOfferedThingAndNotForWhatIsNotOffered() {
    MonitorState s = new MonitorState();
    Set<String> aria = Set.of("update", "getStrings", "getLocState");
    assertFalse(s.firstDataArrived(aria::contains), "nothing yet");
    s.robot = update();
    assertFalse(s.firstDataArrived(aria::contains), "strings and localization still to come");
    s.strings = new InfoStrings(List.of("Network clients"), List.of("1"));
    assertFalse(s.firstDataArrived(aria::contains));
    s.localization = new LocalizationSnapshot("LOCALIZATION_SUCCESS", 0.9, null, 0, false);
    assertTrue(s.firstDataArrived(aria::contains), "all that ARIA's server offers");
    assertFalse(
        s.firstDataArrived(Set.of("update", "getMap")::contains), "the map is offered: wait");
    assertTrue(new MonitorState().firstDataArrived(n -> false), "a server offering nothing");
  }
}
