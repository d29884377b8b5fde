package org.jaria.tools.demo;

import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;

/**
 * Bridges a program's PrintStream output to picocli's writer, a line at a time, so a demo's output
 * goes where the command line says (a test's buffer, or the terminal).
 */
final class WriterOutputStream extends OutputStream {
  private final PrintWriter w;
  private final ByteArrayOutputStream line = new ByteArrayOutputStream();

  WriterOutputStream(PrintWriter w) {
    this.w = w;
  }

  @Override
  public synchronized void write(int b) {
    if (b == '\n') {
      w.println(line.toString(StandardCharsets.UTF_8));
      w.flush();
      line.reset();
    } else {
      line.write(b);
    }
  }

  @Override
  public synchronized void flush() {
    if (line.size() > 0) {
      w.print(line.toString(StandardCharsets.UTF_8));
      line.reset();
    }
    w.flush();
  }
}
