import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;
import org.jaria.params.ArRobotParams;
import org.jaria.protocol.ArRobotPacket;
import org.jaria.protocol.packets.ArConfigPacket;
import org.jaria.protocol.packets.PacketIds;
import org.jaria.protocol.packets.StandardSip;

/**
 * A hand-run comparison: two recordings of the same ARIA program, one against the reference
 * simulator (AMRISim, MobileSim's successor) and one against {@code ./jaria sim --profile
 * mobilesim}, each the hex dump {@code socat -x} wrote while relaying the program's connection.
 * Prints, for every observable a program can read, both values and whether they agree. Run as a
 * single-file program:
 *
 * <pre>
 * java -cp 'tools/target/jaria-tools.jar:tools/target/lib/*' conformance/SideBySide.java \
 *     REFERENCE.hex JARIA.hex
 * </pre>
 *
 * Exit status 0 when nothing differs beyond noise, 1 otherwise.
 */
public class SideBySide {

  /** What one recording shows. */
  static final class Seen {
    final Map<String, String> values = new LinkedHashMap<>();
    final Map<String, Double> numbers = new LinkedHashMap<>();
    /** The first complete laser scan, mm (empty if none). */
    final List<Integer> firstScan = new ArrayList<>();
    /** Transducer to range of the first SIP with sonar readings, before the robot moved. */
    final Map<Integer, Integer> firstSonar = new TreeMap<>();
  }

  public static void main(String[] a) throws IOException {
    Seen ref = observe(Path.of(a[0]));
    Seen got = observe(Path.of(a[1]));
    compareReadings(ref, got);
    TreeSet<String> keys = new TreeSet<>(ref.values.keySet());
    keys.addAll(got.values.keySet());
    int differences = 0;
    System.out.printf("%-44s | %-28s | %-28s | %s%n", "observable", "reference", "jaria", "");
    for (String k : keys) {
      String r = ref.values.getOrDefault(k, "-");
      String g = got.values.getOrDefault(k, "-");
      String verdict;
      if (r.equals(g)) {
        verdict = "same";
      } else if (k.equals("sync2.name") || k.equals("config.NAME")) {
        verdict = "differs (by design: the simulator's own name)";
      } else if (withinNoise(k, ref.numbers.get(k), got.numbers.get(k))) {
        verdict = "same within noise";
      } else {
        verdict = "DIFFERS";
        differences++;
      }
      System.out.printf("%-44s | %-28s | %-28s | %s%n", k, clip(r), clip(g), verdict);
    }
    System.out.println(differences == 0 ? "no differences beyond noise" : differences + " difference(s)");
    System.exit(differences == 0 ? 0 : 1);
  }

  /**
   * The first laser scan and the first sonar readings, reading by reading: both simulators see the
   * same map from the same start, so beyond the sensors' noise (a few mm) they must agree.
   */
  static void compareReadings(Seen ref, Seen got) {
    if (!ref.firstScan.isEmpty() && ref.firstScan.size() == got.firstScan.size()) {
      int apart = 0;
      for (int i = 0; i < ref.firstScan.size(); i++) {
        apart += Math.abs(ref.firstScan.get(i) - got.firstScan.get(i)) > 50 ? 1 : 0;
      }
      ref.values.put("laser.first scan: beams > 50 mm apart", "0");
      got.values.put("laser.first scan: beams > 50 mm apart", "" + apart);
    }
    if (!ref.firstSonar.isEmpty()) {
      List<Integer> apart = new ArrayList<>();
      for (Map.Entry<Integer, Integer> e : ref.firstSonar.entrySet()) {
        Integer g = got.firstSonar.get(e.getKey());
        if (g == null || Math.abs(g - e.getValue()) > 50) {
          apart.add(e.getKey());
        }
      }
      ref.values.put("sip.first sonar: transducers > 50 mm apart", "[]");
      got.values.put("sip.first sonar: transducers > 50 mm apart", apart.toString());
    }
  }

  /** Motion and sensing depend on the simulation's noise: 25 % apart (and 300 mm or 30°) is noise. */
  static boolean withinNoise(String key, Double r, Double g) {
    if (r == null || g == null || !key.startsWith("motion.")) {
      return false;
    }
    double d = Math.abs(r - g);
    double slack = key.endsWith("deg") ? 30 : 300;
    return d <= slack || d <= 0.25 * Math.max(Math.abs(r), Math.abs(g));
  }

  static String clip(String s) {
    return s.length() <= 28 ? s : s.substring(0, 25) + "...";
  }

  static Seen observe(Path hex) throws IOException {
    List<ArRobotPacket> fromRobot = new ArrayList<>();
    List<ArRobotPacket> fromClient = new ArrayList<>();
    readSocatDump(hex, fromRobot, fromClient);
    Seen s = new Seen();
    String subtype = "p3dx-sh";
    int sonarMin = Integer.MAX_VALUE;
    int sonarMax = 0;
    TreeSet<Integer> transducers = new TreeSet<>();
    TreeSet<String> sipIds = new TreeSet<>();
    TreeSet<String> digIn = new TreeSet<>();
    TreeSet<String> digOut = new TreeSet<>();
    TreeSet<Integer> temperatures = new TreeSet<>();
    TreeSet<Integer> optionals = new TreeSet<>();
    int sips = 0;
    StandardSip sip = new StandardSip();
    double[] last = null;
    double path = 0;
    double turned = 0;
    Map<Integer, Integer> laserTotals = new TreeMap<>();
    int noEcho = 0;
    int beyond32m = 0;
    int laserReadings = 0;
    boolean scanDone = false;
    boolean enableSeen = false;
    String motorsAtConnect = "-";
    for (ArRobotPacket p : fromRobot) {
      int id = p.getID();
      if (id == 2 && !s.values.containsKey("sync2.name")) {
        p.resetRead();
        s.values.put("sync2.name", p.bufToString());
        s.values.put("sync2.type", p.bufToString());
        subtype = p.bufToString();
        s.values.put("sync2.subtype", subtype);
      } else if (id == PacketIds.CONFIG && !s.values.containsKey("config.TYPE")) {
        ArConfigPacket c = ArConfigPacket.decode(p);
        if (c != null) {
          for (ArConfigPacket.Field f : ArConfigPacket.Field.values()) {
            String v = !c.has(f) ? "(absent)" : f.isString() ? c.getString(f) : "" + c.getInt(f);
            s.values.put("config." + f, v);
          }
          s.values.put("config.(bytes after the last field)", "" + c.getExtra().length);
        }
      } else if (PacketIds.isStandardSip(id) && sip.decode(p)) {
        sips++;
        if (sips == 1) {
          motorsAtConnect = (sip.getFlags() & 1) != 0 ? "enabled" : "disabled";
        }
        sipIds.add(String.format("0x%02X", id));
        if (s.firstSonar.isEmpty() && sip.getXPos() == 0 && sip.getYPos() == 0) {
          for (int i = 0; i < sip.getSonarCount(); i++) {
            s.firstSonar.put(sip.getSonarNumber(i), sip.getSonarRange(i));
          }
        }
        sonarMin = Math.min(sonarMin, sip.getSonarCount());
        sonarMax = Math.max(sonarMax, sip.getSonarCount());
        for (int i = 0; i < sip.getSonarCount(); i++) {
          transducers.add(sip.getSonarNumber(i));
        }
        int n = 0;
        for (StandardSip.Optional o : StandardSip.Optional.values()) {
          n += sip.has(o) ? 1 : 0;
        }
        optionals.add(n);
        if (sip.has(StandardSip.Optional.DIGOUT)) {
          digIn.add(String.format("0x%02X", sip.getDigIn()));
          digOut.add(String.format("0x%02X", sip.getDigOut()));
        }
        if (sip.has(StandardSip.Optional.TEMPERATURE)) {
          temperatures.add(sip.getTemperature());
        }
        double[] now = {sip.getXPos(), sip.getYPos(), sip.getThPos()};
        if (last != null) {
          path += Math.hypot(wrap15(now[0] - last[0]), wrap15(now[1] - last[1]));
          turned += Math.abs(wrap12(now[2] - last[2]));
        }
        last = now;
      } else if (id == PacketIds.SIM_LASER || id == PacketIds.SIM_LASER_EXTENDED) {
        p.resetRead();
        if (id == PacketIds.SIM_LASER) {
          p.skip(6);
        }
        int total = p.bufToUByte2();
        int first = p.bufToUByte2();
        int n = p.bufToUByte();
        laserTotals.merge(total, 1, Integer::sum);
        boolean record = s.firstScan.size() == first && !scanDone;
        for (int k = 0; k < n && p.remaining() >= 2; k++) {
          int r = p.bufToUByte2();
          if (record) {
            s.firstScan.add(r);
          }
          laserReadings++;
          if (r == 32767) {
            noEcho++;
          } else if (r > 32000) {
            beyond32m++;
          }
          if (id == PacketIds.SIM_LASER_EXTENDED) {
            p.skip(3);
          }
        }
        scanDone |= record && first + n >= total;
      }
    }
    TreeSet<Integer> commands = new TreeSet<>();
    for (ArRobotPacket p : fromClient) {
      commands.add(p.getID());
      enableSeen |= p.getID() == 4;
    }
    double conv = ArRobotParams.forSubtype(subtype).getDistConvFactor();
    double angle = ArRobotParams.forSubtype(subtype).getAngleConvFactor();
    s.values.put("sip.ids", sipIds.toString());
    s.values.put("sip.optional fields", optionals.toString());
    s.values.put("sip.motors at connect", motorsAtConnect);
    s.values.put("sip.sonar readings per SIP", sips == 0 ? "-" : sonarMin + ".." + sonarMax);
    s.values.put("sip.transducers reported", transducers.size() + "");
    s.values.put("sip.DIGIN", digIn.toString());
    s.values.put("sip.DIGOUT", digOut.toString());
    s.values.put("sip.temperature", temperatures.toString());
    s.values.put("laser.readings per scan", laserTotals.keySet().toString());
    s.values.put(
        "laser.no-echo readings (32767)",
        laserReadings == 0 ? "-" : noEcho == 0 ? "none" : "some");
    s.values.put("laser.readings 32001..32766", "" + beyond32m);
    s.values.put("client.sent ENABLE", "" + enableSeen);
    s.values.put("client.commands", commands.toString());
    putNumber(s, "motion.odometry path mm", path * conv);
    putNumber(s, "motion.odometry turned deg", Math.toDegrees(turned * angle));
    return s;
  }

  static void putNumber(Seen s, String k, double v) {
    s.numbers.put(k, v);
    s.values.put(k, String.format(Locale.ROOT, "%.0f", v));
  }

  /** A difference of two 15-bit SIP positions (ARIA masks them to 15 bits). */
  static double wrap15(double d) {
    double m = ((d % 32768) + 32768) % 32768;
    return m > 16384 ? m - 32768 : m;
  }

  /** A difference of two 12-bit SIP headings. */
  static double wrap12(double d) {
    double m = ((d % 4096) + 4096) % 4096;
    return m > 2048 ? m - 4096 : m;
  }

  /**
   * Reads socat's {@code -x} dump: a header line per chunk ("&gt;" from the program to the
   * simulator, "&lt;" back) then the chunk's bytes in hex, and splits each direction into packets.
   */
  static void readSocatDump(Path hex, List<ArRobotPacket> fromRobot, List<ArRobotPacket> fromClient)
      throws IOException {
    java.io.ByteArrayOutputStream toRobot = new java.io.ByteArrayOutputStream();
    java.io.ByteArrayOutputStream toClient = new java.io.ByteArrayOutputStream();
    java.io.ByteArrayOutputStream cur = null;
    for (String line : Files.readAllLines(hex, java.nio.charset.StandardCharsets.ISO_8859_1)) {
      if (line.startsWith(">")) {
        cur = toRobot;
      } else if (line.startsWith("<")) {
        cur = toClient;
      } else if (cur != null && line.startsWith(" ")) {
        for (String b : line.trim().split("\\s+")) {
          if (!b.isEmpty()) {
            cur.write(Integer.parseInt(b, 16));
          }
        }
      }
    }
    split(toClient.toByteArray(), fromRobot);
    split(toRobot.toByteArray(), fromClient);
  }

  static void split(byte[] b, List<ArRobotPacket> out) {
    int i = 0;
    while (i + 3 < b.length) {
      if ((b[i] & 0xFF) == 0xFA && (b[i + 1] & 0xFF) == 0xFB) {
        int n = b[i + 2] & 0xFF;
        if (i + 3 + n > b.length) {
          break;
        }
        ArRobotPacket p = new ArRobotPacket();
        p.load(b, i, 3 + n);
        if (p.verifyCheckSum()) {
          out.add(p);
        }
        i += 3 + n;
      } else {
        i++;
      }
    }
  }
}
