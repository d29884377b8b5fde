package org.jaria.classroom.grading;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * A class's results in numbers: mean and median score, how many students got each score, how many
 * ended with each status, and the checks most students failed.
 *
 * @param students how many students
 * @param mean the mean score
 * @param median the median score
 * @param maxScore the points available
 * @param byScore how many students got each score, highest first
 * @param byStatus how many students ended with each status
 * @param mostFailed check name to how many students failed it on its own (not only withheld for
 *     another check's problem), most first (at most five)
 */
public record ClassStats(
    int students,
    double mean,
    double median,
    int maxScore,
    Map<Integer, Integer> byScore,
    Map<Status, Integer> byStatus,
    Map<String, Integer> mostFailed) {

  /** The statistics of {@code results}. */
  public static ClassStats of(List<Grader.Result> results, int maxScore) {
    List<Integer> scores = new ArrayList<>();
    Map<Integer, Integer> byScore = new TreeMap<>(Comparator.reverseOrder());
    Map<Status, Integer> byStatus = new TreeMap<>();
    Map<String, Integer> failed = new LinkedHashMap<>();
    for (Grader.Result r : results) {
      int s = r.grade().score();
      scores.add(s);
      byScore.merge(s, 1, Integer::sum);
      byStatus.merge(r.status(), 1, Integer::sum);
      for (Check c : r.grade().failures()) {
        if (!c.withheld()) {
          failed.merge(c.name(), 1, Integer::sum);
        }
      }
    }
    scores.sort(null);
    int n = scores.size();
    double mean = scores.stream().mapToInt(Integer::intValue).average().orElse(0);
    double median =
        n == 0
            ? 0
            : n % 2 == 1 ? scores.get(n / 2) : (scores.get(n / 2 - 1) + scores.get(n / 2)) / 2.0;
    Map<String, Integer> most = new LinkedHashMap<>();
    failed.entrySet().stream()
        .sorted(
            Map.Entry.<String, Integer>comparingByValue()
                .reversed()
                .thenComparing(Map.Entry.comparingByKey()))
        .limit(5)
        .forEach(e -> most.put(e.getKey(), e.getValue()));
    return new ClassStats(n, mean, median, maxScore, byScore, byStatus, most);
  }
}
