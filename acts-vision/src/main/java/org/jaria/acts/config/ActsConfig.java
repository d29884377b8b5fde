package org.jaria.acts.config;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.jaria.acts.ActsFormatException;
import org.jaria.acts.ActsProtocol;
import org.jaria.acts.color.Channel;
import org.jaria.acts.color.ChannelBank;
import org.jaria.acts.color.ChannelLutFile;

/**
 * An ACTS runtime configuration (EZ-Train's Save Runtime Config, ACTS's {@code -c}/{@code -t}):
 * which channel LUT files to load and how many blobs each tracks, the image size, the minimum blob
 * size and the server port. Saving a configuration does not save the channel files themselves.
 *
 * <p>File format (see {@link KeyValueLines} for the line syntax):
 *
 * <pre>
 * ; JAria ACTS runtime configuration
 * Width 160
 * Height 120
 * MinBlobSize 5
 * Port 5001
 * Channel 1 channel1.lut 2
 * Channel 2 "green ball.lut" 3
 * </pre>
 *
 * <p>{@code Channel n file blobs}: channel 1..32, its LUT file (relative paths are relative to the
 * configuration file's folder), blobs tracked 1..10. Every keyword is optional except that a
 * channel may appear only once; unknown keywords are errors (they are usually typos).
 *
 * @param width image width in pixels
 * @param height image height in pixels
 * @param minBlobSize minimum blob width and height in pixels
 * @param port TCP port of the server
 * @param channels the channels to load
 */
public record ActsConfig(
    int width, int height, int minBlobSize, int port, List<ChannelEntry> channels) {

  /** One {@code Channel} line. */
  public record ChannelEntry(int channel, String file, int trackedBlobs) {
    /** Checks the ranges. */
    public ChannelEntry {
      ChannelBank.checkChannel(channel);
      if (file == null || file.isBlank()) {
        throw new IllegalArgumentException("channel " + channel + " needs a file name");
      }
      if (trackedBlobs < 1 || trackedBlobs > ChannelBank.MAX_TRACKED_BLOBS) {
        throw new IllegalArgumentException("tracked blobs must be 1..10, got " + trackedBlobs);
      }
    }
  }

  /** ACTS's defaults: 160×120, minimum blob size 5, port 5001, no channels. */
  public static final ActsConfig DEFAULT =
      new ActsConfig(160, 120, 5, ActsProtocol.DEFAULT_PORT, List.of());

  /** Checks the ranges and copies the list. */
  public ActsConfig {
    checkSize("width", width);
    checkSize("height", height);
    checkRange("minimum blob size", minBlobSize, 1, ActsProtocol.MAX_2_DIGITS);
    checkRange("port", port, 0, 65535);
    channels = List.copyOf(channels);
    boolean[] seen = new boolean[ChannelBank.NUM_CHANNELS + 1];
    for (ChannelEntry e : channels) {
      if (seen[e.channel()]) {
        throw new IllegalArgumentException("channel " + e.channel() + " is listed twice");
      }
      seen[e.channel()] = true;
    }
  }

  private static void checkSize(String what, int v) {
    checkRange(what, v, 1, ActsProtocol.MAX_2_DIGITS);
  }

  private static void checkRange(String what, int v, int min, int max) {
    if (v < min || v > max) {
      throw new IllegalArgumentException(what + " must be " + min + ".." + max + ", got " + v);
    }
  }

  /** This configuration with another image size. */
  public ActsConfig withSize(int w, int h) {
    return new ActsConfig(w, h, minBlobSize, port, channels);
  }

  /** This configuration with another port. */
  public ActsConfig withPort(int p) {
    return new ActsConfig(width, height, minBlobSize, p, channels);
  }

  /** This configuration with another minimum blob size. */
  public ActsConfig withMinBlobSize(int size) {
    return new ActsConfig(width, height, size, port, channels);
  }

  // ---------------------------------------------------------------- files

  /** Reads a configuration file. */
  public static ActsConfig read(Path file) throws IOException {
    return fromLines(KeyValueLines.read(file), file.toString());
  }

  /** Parses configuration text; {@code name} is used in messages. */
  public static ActsConfig parse(String text, String name) throws ActsFormatException {
    return fromLines(KeyValueLines.parse(text, name), name);
  }

  private static ActsConfig fromLines(List<KeyValueLines.Line> lines, String name)
      throws ActsFormatException {
    int w = DEFAULT.width;
    int h = DEFAULT.height;
    int min = DEFAULT.minBlobSize;
    int port = DEFAULT.port;
    List<ChannelEntry> channels = new ArrayList<>();
    boolean[] seen = new boolean[ChannelBank.NUM_CHANNELS + 1];
    int max = ActsProtocol.MAX_2_DIGITS;
    for (KeyValueLines.Line l : lines) {
      switch (l.lowerKey()) {
        case "width" -> w = KeyValueLines.intValue(l, 1, max, name);
        case "height" -> h = KeyValueLines.intValue(l, 1, max, name);
        case "minblobsize" -> min = KeyValueLines.intValue(l, 1, max, name);
        case "port" -> port = KeyValueLines.intValue(l, 0, 65535, name);
        case "channel" -> {
          if (l.values().size() != 3) {
            throw new ActsFormatException(
                name, l.number(), "expected 'Channel <1..32> <file> <blobs 1..10>'");
          }
          int n = parseInt(l, l.values().get(0), 1, ChannelBank.NUM_CHANNELS, "channel", name);
          int blobs =
              parseInt(l, l.values().get(2), 1, ChannelBank.MAX_TRACKED_BLOBS, "blobs", name);
          if (seen[n]) {
            throw new ActsFormatException(name, l.number(), "channel " + n + " is listed twice");
          }
          seen[n] = true;
          channels.add(new ChannelEntry(n, l.values().get(1), blobs));
        }
        default ->
            throw new ActsFormatException(
                name,
                l.number(),
                "unknown keyword '"
                    + l.key()
                    + "' (known: Width, Height, MinBlobSize, Port, Channel)");
      }
    }
    return new ActsConfig(w, h, min, port, channels);
  }

  private static int parseInt(
      KeyValueLines.Line l, String v, int min, int max, String what, String name)
      throws ActsFormatException {
    try {
      int x = Integer.parseInt(v);
      if (x >= min && x <= max) {
        return x;
      }
    } catch (NumberFormatException e) {
      // reported below
    }
    throw new ActsFormatException(
        name,
        l.number(),
        what + " must be a whole number " + min + ".." + max + ", got '" + v + "'");
  }

  /** The configuration as file text. */
  public String format() {
    StringBuilder b = new StringBuilder();
    b.append("; JAria ACTS runtime configuration\n");
    b.append("Width ").append(width).append('\n');
    b.append("Height ").append(height).append('\n');
    b.append("MinBlobSize ").append(minBlobSize).append('\n');
    b.append("Port ").append(port).append('\n');
    for (ChannelEntry e : channels) {
      b.append("Channel ")
          .append(e.channel())
          .append(' ')
          .append(KeyValueLines.quote(e.file()))
          .append(' ')
          .append(e.trackedBlobs())
          .append('\n');
    }
    return b.toString();
  }

  /** Writes the configuration (not the channel files). */
  public void write(Path file) throws IOException {
    Files.writeString(file, format(), StandardCharsets.UTF_8);
  }

  // ---------------------------------------------------------------- channels

  /**
   * Loads every listed channel file into {@code bank}, with the tracked-blob counts; channels not
   * listed become empty. All files are read first: if any is missing or damaged, the exception
   * names it and the bank is left exactly as it was.
   *
   * @param baseDir folder that relative channel file names are relative to (usually the
   *     configuration file's folder)
   */
  public void applyTo(ChannelBank bank, Path baseDir) throws IOException {
    Channel[] contents = new Channel[ChannelBank.NUM_CHANNELS];
    int[] tracked = new int[ChannelBank.NUM_CHANNELS];
    String[] names = new String[ChannelBank.NUM_CHANNELS];
    java.util.Arrays.fill(tracked, ChannelBank.DEFAULT_TRACKED_BLOBS);
    for (ChannelEntry e : channels) {
      Path p = baseDir.resolve(e.file());
      if (!Files.isRegularFile(p)) {
        throw new IOException(
            "channel "
                + e.channel()
                + " file "
                + p
                + " does not exist; save the channel from EZ-Train or fix the configuration");
      }
      contents[e.channel() - 1] = ChannelLutFile.read(p);
      tracked[e.channel() - 1] = e.trackedBlobs();
      names[e.channel() - 1] = e.file();
    }
    bank.replaceAll(contents, tracked, names);
  }

  /**
   * A configuration listing the bank's non-empty channels with their file names and tracked-blob
   * counts.
   */
  public static ActsConfig of(ChannelBank bank, int width, int height, int minBlobSize, int port) {
    List<ChannelEntry> list = new ArrayList<>();
    for (int c = 1; c <= ChannelBank.NUM_CHANNELS; c++) {
      if (!bank.copyOf(c).isEmpty()) {
        list.add(new ChannelEntry(c, bank.getFileName(c), bank.getTrackedBlobs(c)));
      }
    }
    return new ActsConfig(width, height, minBlobSize, port, list);
  }
}
