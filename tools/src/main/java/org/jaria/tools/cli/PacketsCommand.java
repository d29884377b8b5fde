package org.jaria.tools.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.Callable;
import org.jaria.protocol.ArRobotPacketReceiver;
import org.jaria.protocol.DropCounters;
import org.jaria.protocol.DropReason;
import org.jaria.protocol.Hex;
import org.jaria.protocol.packets.PacketFormatter;
import org.jaria.util.UserFiles;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code jaria packets}: decodes ARCOS bytes into readable packets. Input is hex text (as
 * arguments, or a file, or standard input) or, with {@code --binary}, a raw capture of the bytes on
 * a serial line or socket.
 */
@Command(
    name = "packets",
    description = {
      "Decode ARCOS bytes (a hex dump or a raw capture) into readable packets.",
      "Examples:",
      "  jaria packets FA FB 06 04 3B 01 00 05 3B",
      "  jaria packets --from robot --file capture.hex",
      "  jaria packets --binary --file serial.bin"
    })
final class PacketsCommand implements Callable<Integer> {

  @Spec CommandSpec spec;

  @Parameters(paramLabel = "HEX", description = "Hex bytes to decode (if no --file).")
  List<String> hex = List.of();

  @Option(
      names = {"-f", "--file"},
      description = "Read from this file ('-' for standard input).")
  String file;

  @Option(names = "--binary", description = "The file holds raw bytes, not hex text.")
  boolean binary;

  @Option(
      names = "--from",
      description = "Who sent the bytes: client, robot or auto (default: ${DEFAULT-VALUE}).",
      defaultValue = "auto")
  String from;

  @Option(names = "--hex", description = "Also print each packet's bytes.")
  boolean showHex;

  @Override
  public Integer call() throws IOException {
    PrintWriter out = spec.commandLine().getOut();
    PrintWriter err = spec.commandLine().getErr();
    PacketFormatter.Direction dir;
    try {
      dir = PacketFormatter.Direction.valueOf(from.toUpperCase(java.util.Locale.ROOT));
    } catch (IllegalArgumentException e) {
      err.println("--from must be client, robot or auto, not '" + from + "'");
      return 2;
    }
    byte[] bytes;
    try {
      bytes = readInput();
    } catch (IllegalArgumentException e) {
      err.println("cannot read the input as hex: " + e.getMessage());
      return 2;
    }
    DropCounters drops = new DropCounters("input");
    ArRobotPacketReceiver receiver = new ArRobotPacketReceiver(drops);
    int[] count = {0};
    receiver.feed(
        bytes,
        0,
        bytes.length,
        0,
        p -> {
          count[0]++;
          out.println(PacketFormatter.describe(p, dir));
          if (showHex) {
            out.println("       " + p.toHexString());
          }
        });
    receiver.checkTimeout(Long.MAX_VALUE, p -> count[0]++);
    out.printf(
        "%d packets, %d bytes skipped, dropped: %d bad checksum, %d bad length, %d incomplete%n",
        count[0],
        drops.skippedBytes(),
        drops.get(DropReason.BAD_CHECKSUM),
        drops.get(DropReason.BAD_LENGTH),
        drops.get(DropReason.TIMEOUT));
    out.flush();
    return 0;
  }

  private byte[] readInput() throws IOException {
    if (file == null) {
      return Hex.parse(String.join(" ", hex));
    }
    if (!"-".equals(file)) {
      Optional<String> problem = UserFiles.problem(file);
      if (problem.isPresent()) {
        throw new IOException(problem.get());
      }
    }
    byte[] raw = "-".equals(file) ? System.in.readAllBytes() : Files.readAllBytes(Path.of(file));
    return binary ? raw : Hex.parse(new String(raw, StandardCharsets.ISO_8859_1));
  }
}
