package org.jaria.classroom.link;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.Map;
import org.jaria.sim.SimOptions;
import org.jaria.sim.SimRobot;
import org.jaria.sim.SimWorld;
import org.junit.jupiter.api.Test;

/**
 * The grader's end of the link against a hostile or broken student side: garbage, a frame claiming
 * a huge length, silence, a System.exit announcement. Each is a {@link LinkLost}, never a hang or a
 * huge allocation.
 */
class StudentLinkTest {

  private static LinkLost connectTo(byte[] studentSends) {
    try (SimWorld world = SimWorld.empty(SimOptions.builder().seed(1).build())) {
      SimRobot r = world.addRobot("p3dx-sh");
      StudentStreams s =
          StudentStreams.of(
              new ByteArrayInputStream(studentSends), OutputStream.nullOutputStream());
      return assertThrows(LinkLost.class, () -> StudentLink.connect(world, r, s, Map.of()));
    }
  }

  @Test
  void garbageIsALostLink() {
    LinkLost e = connectTo("HTTP/1.1 200 OK\r\n\r\n".getBytes(StandardCharsets.US_ASCII));
    assertTrue(e.getMessage().contains("sent frame 'H'"), e.getMessage());
  }

  @Test
  void aHugeLengthIsRefusedBeforeAnythingIsAllocated() throws IOException {
    ByteArrayOutputStream b = new ByteArrayOutputStream();
    DataOutputStream d = new DataOutputStream(b);
    d.writeByte(Frames.REPLY);
    d.writeInt(Integer.MAX_VALUE);
    LinkLost e = connectTo(b.toByteArray());
    assertTrue(e.getMessage().contains("bad frame"), e.getMessage());
  }

  @Test
  void silenceIsALostLink() {
    LinkLost e = connectTo(new byte[0]);
    assertTrue(e.getMessage().contains("ended"), e.getMessage());
  }

  @Test
  void anExitAnnouncementSaysSo() {
    LinkLost e = connectTo(new byte[] {Frames.EXITING});
    assertTrue(e.exiting(), e.getMessage());
  }
}
