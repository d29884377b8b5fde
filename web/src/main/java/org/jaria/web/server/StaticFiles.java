package org.jaria.web.server;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.util.Map;
import org.eclipse.jetty.http.HttpHeader;
import org.eclipse.jetty.http.HttpMethod;
import org.eclipse.jetty.http.HttpStatus;
import org.eclipse.jetty.server.Handler;
import org.eclipse.jetty.server.Request;
import org.eclipse.jetty.server.Response;
import org.eclipse.jetty.util.Callback;

/**
 * The page: a fixed list of files read from the jar once at start. A request names one of them
 * exactly or gets 404; there is no file system behind it, so no path can reach a file outside the
 * page. With a token, every request must carry it ({@code ?token=...}).
 */
final class StaticFiles extends Handler.Abstract.NonBlocking {

  /** URL path to (resource name, content type). */
  static final Map<String, String[]> FILES =
      Map.of(
          "/", new String[] {"index.html", "text/html; charset=utf-8"},
          "/index.html", new String[] {"index.html", "text/html; charset=utf-8"},
          "/app.js", new String[] {"app.js", "text/javascript; charset=utf-8"},
          "/protocol.js", new String[] {"protocol.js", "text/javascript; charset=utf-8"},
          "/draw.js", new String[] {"draw.js", "text/javascript; charset=utf-8"},
          "/style.css", new String[] {"style.css", "text/css; charset=utf-8"},
          "/favicon.svg", new String[] {"favicon.svg", "image/svg+xml"});

  private static final String CSP =
      "default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self' data:;"
          + " connect-src 'self'; base-uri 'none'; form-action 'none'; frame-ancestors 'none'";

  private final Map<String, byte[]> bodies;
  private final WebServer hub;

  StaticFiles(WebServer hub) {
    this.hub = hub;
    Map<String, byte[]> m = new java.util.HashMap<>();
    for (String[] f : FILES.values()) {
      m.computeIfAbsent(f[0], StaticFiles::read);
    }
    bodies = Map.copyOf(m);
  }

  private static byte[] read(String name) {
    try (InputStream in = StaticFiles.class.getResourceAsStream("/org/jaria/web/page/" + name)) {
      if (in == null) {
        throw new IllegalStateException("the web page's " + name + " is missing from the jar");
      }
      return in.readAllBytes();
    } catch (IOException e) {
      throw new UncheckedIOException("cannot read the web page's " + name, e);
    }
  }

  @Override
  public boolean handle(Request request, Response response, Callback callback) {
    String method = request.getMethod();
    boolean head = HttpMethod.HEAD.is(method);
    String[] file = FILES.get(request.getHttpURI().getPath());
    if (!HttpMethod.GET.is(method) && !head) {
      return error(response, callback, HttpStatus.METHOD_NOT_ALLOWED_405, "GET only");
    }
    if (!hub.tokenOk(Request.extractQueryParameters(request).getValue("token"))) {
      hub.counters().notFound.increment();
      return error(
          response, callback, HttpStatus.FORBIDDEN_403, "open the address the server printed");
    }
    if (file == null) {
      hub.counters().notFound.increment();
      return error(response, callback, HttpStatus.NOT_FOUND_404, "not found");
    }
    byte[] body = bodies.get(file[0]);
    response.setStatus(HttpStatus.OK_200);
    var h = response.getHeaders();
    h.put(HttpHeader.CONTENT_TYPE, file[1]);
    h.put(HttpHeader.CACHE_CONTROL, "no-store");
    h.put("X-Content-Type-Options", "nosniff");
    h.put("Referrer-Policy", "no-referrer");
    h.put("Content-Security-Policy", CSP);
    h.put(HttpHeader.CONTENT_LENGTH, String.valueOf(body.length));
    hub.counters().pagesServed.increment();
    response.write(true, head ? ByteBuffer.allocate(0) : ByteBuffer.wrap(body), callback);
    return true;
  }

  private static boolean error(Response response, Callback callback, int status, String text) {
    response.setStatus(status);
    response.getHeaders().put(HttpHeader.CONTENT_TYPE, "text/plain; charset=utf-8");
    response.getHeaders().put("X-Content-Type-Options", "nosniff");
    response.write(
        true,
        ByteBuffer.wrap((text + "\n").getBytes(java.nio.charset.StandardCharsets.UTF_8)),
        callback);
    return true;
  }
}
