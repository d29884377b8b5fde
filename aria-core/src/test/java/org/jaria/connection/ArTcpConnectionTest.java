package org.jaria.connection;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import org.jaria.clock.Clock;
import org.junit.jupiter.api.Test;

class ArTcpConnectionTest {

  @Test
  void talksToARealSocketAndSeesTheOtherEndClose() throws Exception {
    try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      ArTcpConnection c = new ArTcpConnection("127.0.0.1", server.getLocalPort(), Clock.system());
      c.open();
      try (Socket peer = server.accept()) {
        ArTcpConnection p = ArTcpConnection.wrap(peer, Clock.system());
        c.write(new byte[] {1, 2, 3}, 0, 3);
        byte[] buf = new byte[8];
        int n = 0;
        while (n < 3) {
          n += p.read(buf, n, 8 - n, 1000);
        }
        assertEquals(3, buf[2]);
        assertEquals(0, c.read(buf, 0, 8, 0), "nothing waiting: no block, no data");
        assertEquals(0, c.read(buf, 0, 8, 20), "timeout gives 0");
      }
      byte[] buf = new byte[8];
      assertEquals(-1, c.read(buf, 0, 8, 1000));
      assertEquals(ArDeviceConnection.Status.CLOSED_ERROR, c.getStatus());
      c.close();
    }
  }

  @Test
  void refusedConnectionSaysWhatToDo() throws IOException {
    int port;
    try (ServerSocket s = new ServerSocket(0)) {
      port = s.getLocalPort();
    }
    ArTcpConnection c = new ArTcpConnection("127.0.0.1", port, Clock.system());
    IOException e = assertThrows(IOException.class, c::open);
    assertTrue(e.getMessage().contains("./jaria sim"), e.getMessage());
    assertEquals(ArDeviceConnection.Status.OPEN_FAILED, c.getStatus());
    assertEquals(false, c.openSimple());
  }

  @Test
  void closeWhileReadingIsNotAnError() throws Exception {
    try (ServerSocket server = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
      ArTcpConnection c = new ArTcpConnection("127.0.0.1", server.getLocalPort(), Clock.system());
      c.open();
      try (Socket peer = server.accept()) {
        Thread reader =
            new Thread(
                () -> {
                  try {
                    c.read(new byte[4], 0, 4, 10_000);
                  } catch (IOException expected) {
                    // the socket closes under the reader
                  }
                });
        reader.start();
        c.close();
        reader.join(10_000);
        assertEquals(false, reader.isAlive());
        assertEquals(ArDeviceConnection.Status.CLOSED_NORMALLY, c.getStatus());
        assertTrue(peer.isConnected());
      }
    }
  }
}
