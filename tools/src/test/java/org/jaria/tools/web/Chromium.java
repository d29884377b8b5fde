package org.jaria.tools.web;

import com.fasterxml.jackson.core.JsonFactory;
import java.io.IOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.net.http.WebSocket;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;
import org.jaria.web.json.Json;
import org.jaria.web.json.JsonValues;

/**
 * A real headless Chromium (Debian's {@code chromium}) driven over the DevTools protocol, with the
 * JDK's own WebSocket client: navigate, evaluate JavaScript, press keys, click, take screenshots,
 * and collect every console error, uncaught exception and failed load. Started with the flags a
 * test machine needs (no sandbox, no GPU, nothing fetched from the network) and a fresh profile.
 */
final class Chromium implements AutoCloseable {

  private static final JsonFactory JSON = new JsonFactory();

  private final Process process;
  private final Path profile;
  private final WebSocket ws;
  private final AtomicInteger ids = new AtomicInteger();
  private final Map<Integer, CompletableFuture<Map<?, ?>>> pending = new ConcurrentHashMap<>();
  private final List<String> errors = new CopyOnWriteArrayList<>();
  private final List<String> events = new CopyOnWriteArrayList<>();

  private Chromium(Process process, Path profile, URI page) throws Exception {
    this.process = process;
    this.profile = profile;
    this.ws =
        HttpClient.newHttpClient()
            .newWebSocketBuilder()
            .buildAsync(page, new Listener())
            .get(20, TimeUnit.SECONDS);
  }

  /**
   * Starts Chromium with a {@code width} × {@code height} window.
   *
   * @throws IOException if Chromium is not installed (say how to install it) or does not start
   */
  static Chromium start(int width, int height) throws Exception {
    String bin = find();
    Path profile = Files.createTempDirectory("jaria-chromium");
    List<String> cmd =
        List.of(
            bin,
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--no-first-run",
            "--no-default-browser-check",
            "--disable-extensions",
            "--hide-scrollbars",
            "--force-device-scale-factor=1",
            "--user-data-dir=" + profile,
            "--remote-debugging-address=127.0.0.1",
            "--remote-debugging-port=0",
            "--window-size=" + width + "," + height,
            "about:blank");
    Process p =
        new ProcessBuilder(cmd)
            .redirectErrorStream(true)
            .redirectOutput(profile.resolve("chromium.log").toFile())
            .start();
    Path portFile = profile.resolve("DevToolsActivePort");
    long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
    // Chromium writes the port file once it listens; there is no other signal to wait on.
    while (!Files.exists(portFile) || Files.readAllLines(portFile).size() < 2) {
      if (!p.isAlive() || System.nanoTime() > deadline) {
        p.destroyForcibly();
        throw new IOException(
            "Chromium did not start: " + Files.readString(profile.resolve("chromium.log")));
      }
      TimeUnit.MILLISECONDS.sleep(50);
    }
    int port = Integer.parseInt(Files.readAllLines(portFile).get(0).strip());
    String list =
        HttpClient.newHttpClient()
            .send(
                HttpRequest.newBuilder(URI.create("http://127.0.0.1:" + port + "/json/list"))
                    .timeout(Duration.ofSeconds(10))
                    .build(),
                HttpResponse.BodyHandlers.ofString())
            .body();
    for (Object o : (List<?>) JsonValues.read(list, JSON, Integer.MAX_VALUE)) {
      Map<?, ?> t = (Map<?, ?>) o;
      if ("page".equals(t.get("type"))) {
        Chromium c = new Chromium(p, profile, URI.create((String) t.get("webSocketDebuggerUrl")));
        c.call("Runtime.enable", Map.of());
        c.call("Log.enable", Map.of());
        c.call("Page.enable", Map.of());
        c.call(
            "Emulation.setDeviceMetricsOverride",
            Map.of("width", width, "height", height, "deviceScaleFactor", 1, "mobile", false));
        return c;
      }
    }
    p.destroyForcibly();
    throw new IOException("Chromium has no page to drive: " + list);
  }

  private static String find() throws IOException {
    for (String dir : System.getenv().getOrDefault("PATH", "/usr/bin").split(":", -1)) {
      for (String name : List.of("chromium", "chromium-browser", "google-chrome")) {
        Path p = Path.of(dir, name);
        if (Files.isExecutable(p)) {
          return p.toString();
        }
      }
    }
    throw new IOException(
        "no Chromium on the PATH: install it (apt-get install chromium chromium-driver; .ci/run"
            + " does) to run the browser tests");
  }

  /** Calls a DevTools method and waits for its result. */
  Map<?, ?> call(String method, Map<String, ?> params) throws Exception {
    int id = ids.incrementAndGet();
    CompletableFuture<Map<?, ?>> f = new CompletableFuture<>();
    pending.put(id, f);
    String msg =
        Json.string(
            g -> {
              g.writeStartObject();
              g.writeNumberField("id", id);
              g.writeStringField("method", method);
              g.writeFieldName("params");
              writeValue(g, params);
              g.writeEndObject();
            });
    ws.sendText(msg, true).get(10, TimeUnit.SECONDS);
    Map<?, ?> response = f.get(30, TimeUnit.SECONDS);
    if (response.get("error") != null) {
      throw new IOException(method + " failed: " + response.get("error"));
    }
    return (Map<?, ?>) response.get("result");
  }

  private static void writeValue(com.fasterxml.jackson.core.JsonGenerator g, Object v)
      throws IOException {
    if (v instanceof Map<?, ?> m) {
      g.writeStartObject();
      for (var e : m.entrySet()) {
        g.writeFieldName(String.valueOf(e.getKey()));
        writeValue(g, e.getValue());
      }
      g.writeEndObject();
    } else if (v instanceof String s) {
      g.writeString(s);
    } else if (v instanceof Boolean b) {
      g.writeBoolean(b);
    } else if (v instanceof Integer i) {
      g.writeNumber(i);
    } else if (v instanceof Number n) {
      g.writeNumber(n.doubleValue());
    } else {
      g.writeNull();
    }
  }

  /** Opens {@code url} and waits for its load event. */
  void navigate(String url) throws Exception {
    int before = loads();
    call("Page.navigate", Map.of("url", url));
    long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
    while (loads() == before) {
      if (System.nanoTime() > deadline) {
        throw new AssertionError("the page did not load: " + url);
      }
      TimeUnit.MILLISECONDS.sleep(20);
    }
  }

  private int loads() {
    return (int) events.stream().filter("Page.loadEventFired"::equals).count();
  }

  /** The value of a JavaScript expression (JSON-able). */
  Object eval(String expression) throws Exception {
    Map<?, ?> r =
        call(
            "Runtime.evaluate",
            Map.of("expression", expression, "returnByValue", true, "awaitPromise", true));
    if (r.get("exceptionDetails") != null) {
      throw new AssertionError(expression + " threw: " + r.get("exceptionDetails"));
    }
    return ((Map<?, ?>) r.get("result")).get("value");
  }

  /** Waits (up to {@code seconds}) until the expression is true in the page. */
  void waitFor(String expression, int seconds) throws Exception {
    long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
    // The page's state changes with the frames it receives; there is no event to wait on here.
    while (!Boolean.TRUE.equals(eval("!!(" + expression + ")"))) {
      if (System.nanoTime() > deadline) {
        throw new AssertionError("never true in the page: " + expression + "; errors " + errors);
      }
      TimeUnit.MILLISECONDS.sleep(50);
    }
  }

  /** Presses ({@code down}) or releases a key, as a user's keyboard would. */
  void key(String key, int keyCode, boolean down) throws Exception {
    call(
        "Input.dispatchKeyEvent",
        Map.of(
            "type", down ? "keyDown" : "keyUp",
            "key", key,
            "code", key,
            "windowsVirtualKeyCode", keyCode,
            "nativeVirtualKeyCode", keyCode));
  }

  /** Clicks the left mouse button at page coordinates. */
  void click(double x, double y) throws Exception {
    call("Input.dispatchMouseEvent", Map.of("type", "mouseMoved", "x", x, "y", y));
    call(
        "Input.dispatchMouseEvent",
        Map.of("type", "mousePressed", "x", x, "y", y, "button", "left", "clickCount", 1));
    call(
        "Input.dispatchMouseEvent",
        Map.of("type", "mouseReleased", "x", x, "y", y, "button", "left", "clickCount", 1));
  }

  /** A PNG of the page as it is drawn now. */
  byte[] screenshot() throws Exception {
    Map<?, ?> r = call("Page.captureScreenshot", Map.of("format", "png"));
    return Base64.getDecoder().decode((String) r.get("data"));
  }

  /** Console errors, uncaught exceptions and failed loads so far. */
  List<String> errors() {
    return new ArrayList<>(errors);
  }

  @Override
  public void close() throws IOException {
    ws.abort();
    // Chromium's helpers (network service, renderer, zygote) may outlive the browser process for
    // a moment and still write into the profile: they are stopped and awaited too, and files
    // that vanish while the profile is deleted are no error (a walk once failed on one).
    List<ProcessHandle> helpers = process.descendants().toList();
    process.destroy();
    helpers.forEach(ProcessHandle::destroy);
    try {
      if (!process.waitFor(10, TimeUnit.SECONDS)) {
        process.destroyForcibly();
      }
      for (ProcessHandle h : helpers) {
        h.onExit().get(10, TimeUnit.SECONDS);
      }
    } catch (InterruptedException e) {
      Thread.currentThread().interrupt();
      process.destroyForcibly();
    } catch (ExecutionException | TimeoutException e) {
      helpers.forEach(ProcessHandle::destroyForcibly);
    }
    deleteTree(profile);
  }

  private static void deleteTree(Path root) throws IOException {
    Files.walkFileTree(
        root,
        new SimpleFileVisitor<>() {
          @Override
          public FileVisitResult visitFile(Path f, BasicFileAttributes a) throws IOException {
            Files.deleteIfExists(f);
            return FileVisitResult.CONTINUE;
          }

          @Override
          public FileVisitResult visitFileFailed(Path f, IOException e) {
            return FileVisitResult.CONTINUE;
          }

          @Override
          public FileVisitResult postVisitDirectory(Path d, IOException e) throws IOException {
            Files.deleteIfExists(d);
            return FileVisitResult.CONTINUE;
          }
        });
  }

  private final class Listener implements WebSocket.Listener {
    private StringBuilder text = new StringBuilder();

    @Override
    public void onOpen(WebSocket webSocket) {
      webSocket.request(1);
    }

    @Override
    public CompletionStage<?> onText(WebSocket webSocket, CharSequence data, boolean last) {
      text.append(data);
      if (last) {
        handle(text.toString());
        text = new StringBuilder();
      }
      webSocket.request(1);
      return null;
    }

    private void handle(String s) {
      Map<?, ?> m;
      try {
        m = (Map<?, ?>) JsonValues.read(s, JSON, Integer.MAX_VALUE);
      } catch (JsonValues.BadJson e) {
        errors.add("unreadable DevTools message: " + e.getMessage());
        return;
      }
      if (m.get("id") instanceof Number id) {
        CompletableFuture<Map<?, ?>> f = pending.remove(id.intValue());
        if (f != null) {
          f.complete(m);
        }
        return;
      }
      String method = String.valueOf(m.get("method"));
      events.add(method);
      Map<?, ?> p = (Map<?, ?>) m.get("params");
      switch (method) {
        case "Runtime.consoleAPICalled" -> {
          if ("error".equals(p.get("type")) || "assert".equals(p.get("type"))) {
            errors.add("console." + p.get("type") + ": " + p.get("args"));
          }
        }
        case "Runtime.exceptionThrown" -> errors.add("exception: " + p.get("exceptionDetails"));
        case "Log.entryAdded" -> {
          Map<?, ?> entry = (Map<?, ?>) p.get("entry");
          if ("error".equals(entry.get("level"))) {
            errors.add("log: " + entry.get("text") + " " + entry.get("url"));
          }
        }
        default -> {
          // other events are not needed
        }
      }
    }
  }
}
