package org.jaria.tools.cli;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;

/**
 * "Did you mean" for a mistyped option or command: the names a typo is close to, by how many
 * letters one must add, drop, change or swap ({@code --jbos} is one swap from {@code --jobs}), or
 * that start with what was typed. One rule for every command of {@code jaria}.
 */
final class Suggestions {

  private Suggestions() {}

  /** The candidates close to {@code typed}, closest first; empty when none is close. */
  static List<String> similar(String typed, Collection<String> candidates) {
    String t = bare(typed);
    record Scored(String name, int distance) {}
    List<Scored> close = new ArrayList<>();
    for (String c : candidates) {
      String b = bare(c);
      if (b.isEmpty() || t.isEmpty() || typed.startsWith("-") != c.startsWith("-")) {
        continue;
      }
      int d = distance(t, b);
      int allowed = b.length() <= 3 ? 1 : b.length() <= 6 ? 2 : 3;
      boolean prefix = t.length() >= 3 && b.startsWith(t);
      if (d <= allowed || prefix) {
        close.add(new Scored(c, prefix ? 0 : d));
      }
    }
    close.sort(Comparator.comparingInt(Scored::distance).thenComparing(Scored::name));
    return close.stream().map(Scored::name).distinct().limit(3).toList();
  }

  /** The name without its dashes, in lower case. */
  private static String bare(String s) {
    int i = 0;
    while (i < s.length() && s.charAt(i) == '-') {
      i++;
    }
    return s.substring(i).toLowerCase(Locale.ROOT);
  }

  /**
   * The optimal string alignment distance: insertions, deletions, substitutions and swaps of two
   * neighbouring letters each count one.
   */
  static int distance(String a, String b) {
    int[][] d = new int[a.length() + 1][b.length() + 1];
    for (int i = 0; i <= a.length(); i++) {
      d[i][0] = i;
    }
    for (int j = 0; j <= b.length(); j++) {
      d[0][j] = j;
    }
    for (int i = 1; i <= a.length(); i++) {
      for (int j = 1; j <= b.length(); j++) {
        int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
        int v = Math.min(Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + cost);
        if (i > 1
            && j > 1
            && a.charAt(i - 1) == b.charAt(j - 2)
            && a.charAt(i - 2) == b.charAt(j - 1)) {
          v = Math.min(v, d[i - 2][j - 2] + 1);
        }
        d[i][j] = v;
      }
    }
    return d[a.length()][b.length()];
  }
}
