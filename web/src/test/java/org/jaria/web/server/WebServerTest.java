package org.jaria.web.server;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.net.Socket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.jaria.web.control.Controls;
import org.jaria.web.control.RecordingControls;
import org.jaria.web.json.JsonValues;
import org.junit.jupiter.api.Test;

/**
 * The server as its clients meet it, over real sockets on the loopback: the page and nothing else
 * over HTTP, Foxglove's protocol over the WebSocket, and every kind of bad input counted and
 * refused without stopping the others.
 */
class WebServerTest {

  static WebServer start(WebOptions o, Controls c) throws IOException {
    return WebServer.start(o, new FakeSource(0), c);
  }

  static int status(URI uri, String method) throws Exception {
    HttpRequest req =
        HttpRequest.newBuilder(uri).method(method, HttpRequest.BodyPublishers.noBody()).build();
    return HttpClient.newHttpClient()
        .send(req, HttpResponse.BodyHandlers.discarding())
        .statusCode();
  }

  /** A raw request line, as a browser would never send it (paths that try to leave the page). */
  static String raw(int port, String path) throws IOException {
    try (Socket s = new Socket(java.net.InetAddress.getLoopbackAddress(), port)) {
      s.setSoTimeout(10_000);
      OutputStream out = s.getOutputStream();
      out.write(
          ("GET " + path + " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
              .getBytes(StandardCharsets.ISO_8859_1));
      out.flush();
      InputStream in = s.getInputStream();
      return new String(in.readAllBytes(), StandardCharsets.ISO_8859_1);
    }
  }

  /** Waits for a counter another thread updates; there is no event to wait on. */
  static void eventually(BooleanSupplier done, String what) throws InterruptedException {
    long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
    while (!done.getAsBoolean()) {
      if (System.nanoTime() > deadline) {
        throw new AssertionError("never happened: " + what);
      }
      TimeUnit.MILLISECONDS.sleep(20);
    }
  }

  static Map<?, ?> json(WsClient.Received r) throws Exception {
    return (Map<?, ?>)
        JsonValues.read(r.text(), new com.fasterxml.jackson.core.JsonFactory(), Integer.MAX_VALUE);
  }

  static long channel(Map<?, ?> advertise, String topic) {
    for (Object o : (List<?>) advertise.get("channels")) {
      Map<?, ?> c = (Map<?, ?>) o;
      if (c.get("topic").equals(topic)) {
        return (Long) c.get("id");
      }
    }
    throw new AssertionError("no channel " + topic + " in " + advertise);
  }

  @Test
  void servesThePageAndNothingElse() throws Exception {
    try (WebServer s = start(WebOptions.loopback(0), Controls.NONE)) {
      URI base = URI.create("http://127.0.0.1:" + s.port());
      HttpResponse<String> page =
          HttpClient.newHttpClient()
              .send(
                  HttpRequest.newBuilder(base.resolve("/")).build(),
                  HttpResponse.BodyHandlers.ofString());
      assertEquals(200, page.statusCode());
      assertTrue(page.body().contains("<canvas id=\"view\""));
      assertTrue(
          page.headers()
              .firstValue("Content-Security-Policy")
              .orElse("")
              .contains("default-src 'none'"));
      assertTrue(page.headers().firstValue("Server").isEmpty(), "no server version is given away");
      for (String f :
          List.of("/app.js", "/protocol.js", "/draw.js", "/style.css", "/favicon.svg")) {
        assertEquals(200, status(base.resolve(f), "GET"), f);
      }
      for (String f :
          List.of("/index.htm", "/org/jaria/web/page/app.js", "/WEB-INF/web.xml", "/app.js/")) {
        assertEquals(404, status(base.resolve(f), "GET"), f);
      }
      assertEquals(405, status(base.resolve("/"), "POST"));
      assertEquals(405, status(base.resolve("/app.js"), "DELETE"));
      for (String path :
          List.of(
              "/../../../../etc/passwd",
              "/..%2f..%2f..%2fetc%2fpasswd",
              "/%2e%2e/%2e%2e/etc/passwd",
              "/app.js%00.html",
              "//etc/passwd",
              "/org/jaria/web/server/WebServer.class",
              "/pom.xml")) {
        String response = raw(s.port(), path);
        assertFalse(
            response.startsWith("HTTP/1.1 200"),
            path + ": " + response.lines().findFirst().orElse(""));
        assertFalse(response.contains("root:"), path);
      }
      assertTrue(s.stats().notFound() >= 4, s.stats().toString());
    }
  }

  @Test
  void speaksFoxglovesProtocol() throws Exception {
    try (WebServer s = start(WebOptions.loopback(0), Controls.NONE);
        WsClient c = WsClient.connect(s.websocketUrl())) {
      Map<?, ?> info = json(c.nextText("serverInfo"));
      assertEquals("JAria web view", info.get("name"));
      assertEquals(List.of(), info.get("capabilities"), "read-only: no client publishing");
      assertEquals(List.of("json"), info.get("supportedEncodings"));
      Map<?, ?> adv = json(c.nextText("advertise"));
      long clock = channel(adv, "/clock");
      long map = channel(adv, "/map");
      Map<?, ?> first = (Map<?, ?>) ((List<?>) adv.get("channels")).get(0);
      assertEquals("json", first.get("encoding"));
      assertEquals("jsonschema", first.get("schemaEncoding"));
      c.send(
          "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":7,\"channelId\":"
              + clock
              + "},{\"id\":9,\"channelId\":"
              + map
              + "}]}");
      // the map is sent at once to a new subscriber, then every frame carries the clock
      WsClient.Received m = c.next(r -> !r.isText() && r.binary().getInt(1) == 9);
      assertEquals(1, m.binary().get(0), "opcode: message data");
      String mapJson = new String(body(m.binary()), StandardCharsets.UTF_8);
      assertTrue(mapJson.contains("\"id\":\"walls\""), mapJson);
      WsClient.Received a = c.next(r -> !r.isText() && r.binary().getInt(1) == 7);
      WsClient.Received b = c.next(r -> !r.isText() && r.binary().getInt(1) == 7);
      long ta = a.binary().getLong(5);
      long tb = b.binary().getLong(5);
      assertTrue(tb > ta, "time stamps grow: " + ta + " then " + tb);
      c.send("{\"op\":\"unsubscribe\",\"subscriptionIds\":[7,9]}");
      eventually(() -> s.stats().messagesSent() > 0, "messages sent");
    }
  }

  @Test
  void refusesOtherProtocolsWrongTokensAndTooManyClients() throws Exception {
    WebOptions o =
        new WebOptions("127.0.0.1", 0, false, "s3cret", 2, 10, 65536, 1 << 20, 3000, "t");
    try (WebServer s = start(o, Controls.NONE)) {
      URI page = URI.create("http://127.0.0.1:" + s.port() + "/");
      assertEquals(403, status(page, "GET"));
      assertEquals(403, status(URI.create(page + "?token=wrong"), "GET"));
      assertEquals(200, status(URI.create(page + "?token=s3cret"), "GET"));
      assertEquals(URI.create(page + "?token=s3cret"), s.url());
      URI ws = URI.create("ws://127.0.0.1:" + s.port() + "/");
      assertThrows(Exception.class, () -> WsClient.connect(ws));
      assertThrows(Exception.class, () -> WsClient.withProtocols(s.websocketUrl()));
      assertThrows(Exception.class, () -> WsClient.withProtocols(s.websocketUrl(), "other"));
      try (WsClient a = WsClient.connect(s.websocketUrl());
          WsClient b = WsClient.connect(s.websocketUrl())) {
        a.nextText("serverInfo");
        b.nextText("serverInfo");
        assertThrows(Exception.class, () -> WsClient.connect(s.websocketUrl()));
      }
      assertEquals(4, s.stats().clientsRefused());
    }
  }

  @Test
  void aServerBoundBeyondTheLoopbackHasAToken() {
    assertNull(WebOptions.loopback(0).token());
    String token = WebOptions.loopback(0).withBind("0.0.0.0").token();
    assertNotNull(token);
    assertEquals(32, token.length());
    assertFalse(WebOptions.loopback(0).withBind("0.0.0.0").toString().contains(token));
    assertNull(WebOptions.loopback(0).withBind("::1").token());
  }

  @Test
  void badInputIsCountedAnsweredAndHarmless() throws Exception {
    RecordingControls controls = new RecordingControls();
    try (WebServer s = start(WebOptions.loopback(0), new Controls(controls, controls));
        WsClient c = WsClient.connect(s.websocketUrl())) {
      c.nextText("serverInfo");
      c.send("{not json");
      assertTrue(c.nextText("status").text().contains("malformed"));
      c.send("{\"op\":\"fetchAsset\",\"uri\":\"file:///etc/passwd\",\"requestId\":1}");
      assertTrue(c.nextText("status").text().contains("unsupported operation: fetchAsset"));
      c.send(
          "{\"op\":\"advertise\",\"channels\":[{\"id\":1,\"topic\":\"/cmd_vel\",\"encoding\":\"json\"}]}");
      assertTrue(c.nextText("status").text().contains("read-only"));
      c.send(ByteBuffer.wrap(new byte[] {1, 1, 0, 0, 0, '{', '}'}));
      c.nextText("status");
      c.send(ByteBuffer.wrap(new byte[] {9}));
      c.nextText("status");
      WebStats st = s.stats();
      assertEquals(2, st.malformed(), st.toString());
      assertEquals(1, st.unknownOps(), st.toString());
      assertEquals(2, st.refused(), st.toString());
      assertEquals(List.of(), controls.calls, "a read-only server drives nothing");
      // and the connection still works
      c.send("{\"op\":\"subscribe\",\"subscriptions\":[]}");
      c.send("\"x\"");
      c.nextText("status");
    }
  }

  @Test
  void aMessageOverTheSizeLimitClosesItsConnection() throws Exception {
    try (WebServer s = start(WebOptions.loopback(0), Controls.NONE);
        WsClient c = WsClient.connect(s.websocketUrl());
        WsClient other = WsClient.connect(s.websocketUrl())) {
      c.nextText("serverInfo");
      other.nextText("serverInfo");
      var unused = c.ws.sendText("x".repeat(200_000), true);
      assertEquals(1009, c.closed.get(20, TimeUnit.SECONDS));
      eventually(() -> s.stats().oversized() == 1, "oversized counted");
      other.send("{\"op\":\"nope\"}");
      other.nextText("status");
    }
  }

  @Test
  void aFloodIsDroppedAndThenDisconnected() throws Exception {
    // Time stands still, so the allowance never refills: the burst passes, the rest is flooding,
    // however slowly this machine sends.
    try (WebServer s =
            WebServer.start(WebOptions.loopback(0), new FakeSource(0), Controls.NONE, () -> 0L);
        WsClient c = WsClient.connect(s.websocketUrl())) {
      c.nextText("serverInfo");
      for (int i = 0; i < 3000 && !c.closed.isDone(); i++) {
        var unused = c.ws.sendText("{\"op\":\"unsubscribe\",\"subscriptionIds\":[1]}", true);
      }
      // The server's close (1008, policy violation) can reach a client still sending as a broken
      // connection instead (-1): either way the server ended it.
      int code = c.closed.get(30, TimeUnit.SECONDS);
      assertTrue(code == 1008 || code == -1, "closed by the server: " + code);
      eventually(() -> s.stats().clients() == 0, "the flooder is gone");
      assertTrue(s.stats().flooded() >= ClientConnection.FLOOD_CLOSE, s.stats().toString());
    }
  }

  @Test
  void controlGoesToTheControlsWhenAllowed() throws Exception {
    RecordingControls controls = new RecordingControls();
    try (WebServer s =
            start(WebOptions.loopback(0).withControl(true), new Controls(controls, controls));
        WsClient c = WsClient.connect(s.websocketUrl())) {
      Map<?, ?> info = json(c.nextText("serverInfo"));
      assertEquals(List.of("clientPublish"), info.get("capabilities"));
      assertEquals("drive,goal,sim", ((Map<?, ?>) info.get("metadata")).get("jaria.control"));
      c.send(
          "{\"op\":\"advertise\",\"channels\":[{\"id\":3,\"topic\":\"/cmd_vel\",\"encoding\":\"json\",\"schemaName\":\"Twist\"},"
              + "{\"id\":4,\"topic\":\"/sim/control\",\"encoding\":\"json\",\"schemaName\":\"x\"}]}");
      c.send(publish(3, "{\"linear\":{\"x\":0.3},\"angular\":{\"z\":0}}"));
      c.send(publish(4, "{\"command\":\"pause\"}"));
      c.send(publish(4, "{\"command\":\"speed\",\"value\":-1}"));
      String status = c.nextText("status").text();
      assertTrue(status.contains("speed needs"), status);
      eventually(() -> controls.calls.size() == 2, "two commands carried out");
      assertEquals(List.of("drive 300.0 0.0", "pause"), controls.calls);
      assertEquals(2, s.stats().controlCommands());
    }
  }

  /** A message's payload (after the 13-byte header). */
  static byte[] body(ByteBuffer b) {
    byte[] out = new byte[b.limit() - 13];
    b.get(13, out);
    return out;
  }

  static ByteBuffer publish(int channel, String json) {
    byte[] b = json.getBytes(StandardCharsets.UTF_8);
    return ByteBuffer.allocate(5 + b.length)
        .order(ByteOrder.LITTLE_ENDIAN)
        .put((byte) 1)
        .putInt(channel)
        .put(b)
        .flip();
  }

  @Test
  @org.junit.jupiter.api.Tag("slow") // fills a socket's buffers at 30 frames a second
  void aClientThatStopsReadingLosesMessagesThenItsConnectionAndOthersGoOn() throws Exception {
    WebOptions o = WebOptions.loopback(0).withLimits(8, 65536, 65536, 500).withRate(30);
    try (WebServer s = WebServer.start(o, new FakeSource(20_000), Controls.NONE);
        WsClient slow = WsClient.stalled(s.websocketUrl());
        WsClient fine = WsClient.connect(s.websocketUrl())) {
      Map<?, ?> adv = json(fine.nextText("advertise"));
      long particles = channel(adv, "/robot/particles");
      String sub =
          "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":" + particles + "}]}";
      slow.send(sub);
      fine.send(sub);
      eventually(() -> s.stats().slowClientsClosed() == 1, "the slow client disconnected");
      assertTrue(s.stats().messagesDropped() > 0, s.stats().toString());
      fine.drain();
      fine.next(r -> !r.isText() && r.binary().getInt(1) == 1);
      assertEquals(1, s.stats().slowClientsClosed());
    }
  }

  @Test
  void aRecordingSinkGetsEveryMessageAndCloseEndsIt() throws Exception {
    java.util.List<String> topics = new java.util.concurrent.CopyOnWriteArrayList<>();
    java.util.concurrent.atomic.AtomicBoolean closed =
        new java.util.concurrent.atomic.AtomicBoolean();
    WebServer s = start(WebOptions.loopback(0), Controls.NONE);
    int port = s.port();
    s.addSink(
        new MessageSink() {
          @Override
          public void write(
              org.jaria.web.foxglove.Channel channel, org.jaria.web.foxglove.Message m) {
            topics.add(m.topic());
          }

          @Override
          public void close() {
            closed.set(true);
          }
        });
    eventually(() -> topics.contains("/clock") && topics.contains("/robot/true_pose"), "recorded");
    s.close();
    assertTrue(closed.get());
    assertThrows(
        IOException.class,
        () -> new Socket(java.net.InetAddress.getLoopbackAddress(), port).close());
  }
}
