package org.jaria.classroom.grading;

import java.nio.file.Path;
import java.time.Duration;

/**
 * What a teacher asks {@code jaria grade} for, as plain values: which assignment, whose
 * submissions, where the reports go and how to run the students' programs. {@link ClassGrading}
 * carries it out; the command line only fills it in.
 *
 * @param assignment the assignment's id (square, wall, goals, ball)
 * @param submissions a folder with one folder per student, or one student's folder
 * @param out where the reports and each student's files go (outside {@code submissions})
 * @param timeout real time allowed per student
 * @param jobs how many students are graded at once (the results do not depend on it)
 * @param only re-grade only this student into the existing report in {@code out}, or null for all
 * @param lang the language of the reports and feedback: en or es
 * @param unsafe grade even where no isolation is available (every report then says so)
 * @param bwrap the bubblewrap program that isolates the submissions
 */
public record GradeRequest(
    String assignment,
    Path submissions,
    Path out,
    Duration timeout,
    int jobs,
    String only,
    String lang,
    boolean unsafe,
    Path bwrap) {

  /** Real time per student unless asked otherwise. */
  public static final Duration DEFAULT_TIMEOUT = Duration.ofSeconds(60);

  /** Where bubblewrap is on Debian and Ubuntu. */
  public static final Path DEFAULT_BWRAP = Path.of("/usr/bin/bwrap");

  /**
   * Grades all of {@code submissions} for {@code assignment} into {@code out}: one student at a
   * time, {@link #DEFAULT_TIMEOUT} each, in English, isolated by {@link #DEFAULT_BWRAP}.
   */
  public static GradeRequest of(String assignment, Path submissions, Path out) {
    return new GradeRequest(
        assignment, submissions, out, DEFAULT_TIMEOUT, 1, null, "en", false, DEFAULT_BWRAP);
  }

  /** This request with {@code t} per student. */
  public GradeRequest withTimeout(Duration t) {
    return new GradeRequest(assignment, submissions, out, t, jobs, only, lang, unsafe, bwrap);
  }

  /** This request grading {@code n} students at once. */
  public GradeRequest withJobs(int n) {
    return new GradeRequest(assignment, submissions, out, timeout, n, only, lang, unsafe, bwrap);
  }

  /** This request re-grading only {@code student} into the existing report. */
  public GradeRequest onlyStudent(String student) {
    return new GradeRequest(
        assignment, submissions, out, timeout, jobs, student, lang, unsafe, bwrap);
  }

  /** This request writing reports and feedback in {@code language} (en or es). */
  public GradeRequest inLanguage(String language) {
    return new GradeRequest(
        assignment, submissions, out, timeout, jobs, only, language, unsafe, bwrap);
  }

  /** This request grading without isolation where none is available. */
  public GradeRequest withoutIsolation() {
    return new GradeRequest(assignment, submissions, out, timeout, jobs, only, lang, true, bwrap);
  }

  /** This request isolating the submissions with the bubblewrap program at {@code program}. */
  public GradeRequest withBwrap(Path program) {
    return new GradeRequest(
        assignment, submissions, out, timeout, jobs, only, lang, unsafe, program);
  }
}
