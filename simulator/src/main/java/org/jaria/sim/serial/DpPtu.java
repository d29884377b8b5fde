package org.jaria.sim.serial;

import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.function.Consumer;

/**
 * A Directed Perception PTU-46-17.5 pan-tilt unit on an AUX port, answering its ASCII command
 * language as the unit does, so ARIA's {@code ArDPPTU} and JAria's run against it over the wire.
 *
 * <p>Commands are letters, an optional signed number, and a delimiter (space, CR or LF); letters
 * are case-insensitive. Every command gets one line of answer ending CR LF:
 *
 * <ul>
 *   <li>{@code *} for a command done ({@code PP1000 } → {@code "*\r\n"});
 *   <li>{@code * <text>} for a query: {@code PP} → {@code "* Current Pan position is 1000"}, {@code
 *       TP} → {@code "* Current Tilt position is -200"}, {@code PR}/{@code TR} → {@code "* 185.1428
 *       seconds arc per position"}, {@code PS}/{@code TS} → {@code "* Target Pan speed is 1000
 *       positions/sec"}, {@code PN}/{@code PX}/{@code TN}/{@code TX} → the position limits; in
 *       terse feedback mode ({@code FT}) just {@code "* <number>"};
 *   <li>{@code !} and a reason for an error ({@code "! Maximum allowable Pan position exceeded"},
 *       {@code "! Illegal command"}).
 * </ul>
 *
 * <p>Positions are steps of 185.1428 arc-seconds (0.0514°); pan −3090..3090 (±159°), tilt −907..604
 * (−46.6°..+31°), positive to the right and up. The head reaches a commanded position at once. Echo
 * is off. Not thread-safe: the world thread uses it.
 */
public final class DpPtu implements AuxSerialDevice, PtzHead {

  /** Arc-seconds per position step, both axes. */
  public static final double ARC_SECONDS_PER_STEP = 185.1428;

  /** Degrees per position step. */
  public static final double DEG_PER_STEP = ARC_SECONDS_PER_STEP / 3600;

  /** Pan limit, steps either way. */
  public static final int MAX_PAN = 3090;

  /** Lowest tilt, steps. */
  public static final int MIN_TILT = -907;

  /** Highest tilt, steps. */
  public static final int MAX_TILT = 604;

  /** Longest command the unit takes before it calls it garbage. */
  private static final int MAX_COMMAND = 32;

  private final StringBuilder command = new StringBuilder();
  private boolean terse;
  private boolean immediate = true;
  private int pan;
  private int tilt;
  private int panSpeed = 1000;
  private int tiltSpeed = 1000;
  private long commands;
  private long errors;

  @Override
  public String name() {
    return "dpptu";
  }

  @Override
  public void receive(byte[] data, Consumer<byte[]> reply) {
    for (byte b : data) {
      char c = (char) (b & 0xFF);
      if (c == ' ' || c == '\r' || c == '\n') {
        if (command.length() > 0) {
          String line = answer(command.toString().toUpperCase(Locale.ROOT));
          command.setLength(0);
          reply.accept((line + "\r\n").getBytes(StandardCharsets.US_ASCII));
        }
      } else if (command.length() < MAX_COMMAND) {
        command.append(c);
      }
    }
  }

  /** Executes one command (upper case, no delimiter) and returns the answer line without CR LF. */
  String answer(String c) {
    commands++;
    if (c.equals("@")) {
      return "*"; // ARIA's init character
    }
    int split = 0;
    while (split < c.length() && Character.isLetter(c.charAt(split))) {
      split++;
    }
    String letters = c.substring(0, split);
    String rest = c.substring(split);
    Integer value = null;
    if (!rest.isEmpty()) {
      try {
        value = Integer.valueOf(rest);
      } catch (NumberFormatException e) {
        return error("Illegal argument");
      }
    }
    return switch (letters) {
      case "PP", "TP", "PO", "TO" -> position(letters, value);
      case "PS", "TS" -> speed(letters.charAt(0) == 'P', value);
      case "PR", "TR" ->
          value == null
              ? query(fmt(ARC_SECONDS_PER_STEP), "seconds arc per position")
              : error("Illegal argument");
      case "PN" -> limit("Minimum Pan position is ", -MAX_PAN);
      case "PX" -> limit("Maximum Pan position is ", MAX_PAN);
      case "TN" -> limit("Minimum Tilt position is ", MIN_TILT);
      case "TX" -> limit("Maximum Tilt position is ", MAX_TILT);
      case "FT", "FV" -> {
        terse = letters.equals("FT");
        yield "*";
      }
      case "I", "S" -> {
        immediate = letters.equals("I");
        yield "*";
      }
      // halt, await, reset, limits, echo, control mode, defaults, power modes, accelerations,
      // base and upper/lower speeds: accepted; the simulated head has no dynamics to change
      case "H",
          "HP",
          "HT",
          "A",
          "R",
          "RD",
          "RE",
          "RP",
          "RT",
          "LE",
          "LD",
          "ED",
          "EE",
          "CI",
          "CV",
          "DS",
          "DR",
          "DF",
          "PA",
          "TA",
          "PB",
          "TB",
          "PU",
          "TU",
          "PL",
          "TL",
          "PHO",
          "PHL",
          "PHR",
          "THO",
          "THL",
          "THR",
          "PML",
          "PMR",
          "PMH",
          "TML",
          "TMR",
          "TMH" ->
          "*";
      default -> error("Illegal command");
    };
  }

  private String position(String letters, Integer value) {
    boolean isPan = letters.charAt(0) == 'P';
    String axis = isPan ? "Pan" : "Tilt";
    if (value == null) {
      if (letters.charAt(1) == 'O') {
        return error("Illegal command");
      }
      return query(Integer.toString(isPan ? pan : tilt), null, "Current " + axis + " position is ");
    }
    int target = letters.charAt(1) == 'O' ? (isPan ? pan : tilt) + value : value;
    int lo = isPan ? -MAX_PAN : MIN_TILT;
    int hi = isPan ? MAX_PAN : MAX_TILT;
    if (target > hi) {
      return error("Maximum allowable " + axis + " position exceeded");
    }
    if (target < lo) {
      return error("Minimum allowable " + axis + " position exceeded");
    }
    if (isPan) {
      pan = target;
    } else {
      tilt = target;
    }
    return "*";
  }

  private String speed(boolean isPan, Integer value) {
    if (value == null) {
      return query(
          Integer.toString(isPan ? panSpeed : tiltSpeed),
          "positions/sec",
          "Target " + (isPan ? "Pan" : "Tilt") + " speed is ");
    }
    if (value < 0 || value > 4000) {
      return error("Illegal speed");
    }
    if (isPan) {
      panSpeed = value;
    } else {
      tiltSpeed = value;
    }
    return "*";
  }

  private String limit(String text, int v) {
    return query(Integer.toString(v), null, text);
  }

  private String query(String number, String unit) {
    return query(number, unit, "");
  }

  /** A query's answer: verbose {@code * <prefix><number>[ unit]}, terse {@code * <number>}. */
  private String query(String number, String unit, String prefix) {
    if (terse) {
      return "* " + number;
    }
    return "* " + prefix + number + (unit == null ? "" : " " + unit);
  }

  private String error(String why) {
    errors++;
    return "! " + why;
  }

  private static String fmt(double v) {
    return String.format(Locale.ROOT, "%.4f", v);
  }

  @Override
  public Pointing pointing() {
    return new Pointing(getPan(), getTilt(), 0);
  }

  /** Pan, degrees, positive to the right. */
  public double getPan() {
    return pan * DEG_PER_STEP;
  }

  /** Tilt, degrees, positive up. */
  public double getTilt() {
    return tilt * DEG_PER_STEP;
  }

  /** Pan, steps. */
  public int getPanSteps() {
    return pan;
  }

  /** Tilt, steps. */
  public int getTiltSteps() {
    return tilt;
  }

  /** Pan speed, steps per second. */
  public int getPanSpeed() {
    return panSpeed;
  }

  /** Whether position commands run at once ({@code I}) rather than waiting ({@code S}). */
  public boolean isImmediate() {
    return immediate;
  }

  /** Commands received. */
  public long commands() {
    return commands;
  }

  /** Commands answered with an error. */
  public long errors() {
    return errors;
  }
}
