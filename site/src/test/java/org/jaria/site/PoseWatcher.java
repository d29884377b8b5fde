package org.jaria.site;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.WebSocket;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Watches a web view as its page does, over Foxglove's protocol: subscribes to every robot's {@code
 * true_pose} and remembers how far the first robot got from where it was first seen.
 */
final class PoseWatcher implements WebSocket.Listener, AutoCloseable {

  private static final Pattern TRUE_POSE =
      Pattern.compile("\\{\"id\":(\\d+),\"topic\":\"/[^\"]+/true_pose\"");
  private static final Pattern XY =
      Pattern.compile("\"position\":\\{\"x\":(-?[0-9.eE-]+),\"y\":(-?[0-9.eE-]+)");

  private final WebSocket ws;
  private final StringBuilder text = new StringBuilder();
  private volatile double x0 = Double.NaN;
  private volatile double y0;
  private volatile double farthest;

  private PoseWatcher(URI page) throws Exception {
    URI ws = URI.create(page.toString().replaceFirst("^http", "ws"));
    this.ws =
        HttpClient.newHttpClient()
            .newWebSocketBuilder()
            .subprotocols("foxglove.websocket.v1")
            .buildAsync(ws, this)
            .get(20, TimeUnit.SECONDS);
  }

  static PoseWatcher open(URI page) throws Exception {
    return new PoseWatcher(page);
  }

  /** The farthest the robot was seen from where it was first seen, mm. */
  double farthestMm() {
    return farthest;
  }

  @Override
  public void onOpen(WebSocket w) {
    w.request(1);
  }

  @Override
  public CompletionStage<?> onText(WebSocket w, CharSequence data, boolean last) {
    text.append(data);
    if (last) {
      Matcher m = TRUE_POSE.matcher(text);
      if (m.find()) {
        var unused =
            w.sendText(
                "{\"op\":\"subscribe\",\"subscriptions\":[{\"id\":1,\"channelId\":"
                    + m.group(1)
                    + "}]}",
                true);
      }
      text.setLength(0);
    }
    w.request(1);
    return null;
  }

  @Override
  public CompletionStage<?> onBinary(WebSocket w, ByteBuffer data, boolean last) {
    ByteBuffer b = data.duplicate().order(ByteOrder.LITTLE_ENDIAN);
    if (b.remaining() > 13 && b.get(0) == 1 && b.getInt(1) == 1) {
      byte[] json = new byte[b.remaining() - 13];
      b.position(b.position() + 13).get(json);
      Matcher m = XY.matcher(new String(json, StandardCharsets.UTF_8));
      if (m.find()) {
        double x = Double.parseDouble(m.group(1)) * 1000;
        double y = Double.parseDouble(m.group(2)) * 1000;
        if (Double.isNaN(x0)) {
          x0 = x;
          y0 = y;
        }
        farthest = Math.max(farthest, Math.hypot(x - x0, y - y0));
      }
    }
    w.request(1);
    return null;
  }

  @Override
  public void close() {
    ws.abort();
  }
}
