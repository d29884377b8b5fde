package org.jaria.classroom.classgrading;

import java.nio.file.Path;
import java.time.Clock;
import java.time.Duration;
import java.util.List;
import org.jaria.classroom.platform.Platform;

/**
 * What a teacher asks {@code jaria grade} for, as plain values: which assignment, whose
 * submissions, where the reports go and how to run the students' programs. {@link ClassGrading}
 * carries it out; the command line only fills it in.
 *
 * @param assignment the assignment's id (square, wall, goals, ball, or one of a pack's)
 * @param submissions a folder with one folder per student, or one student's folder
 * @param out where the reports and each student's files go (outside {@code submissions})
 * @param timeout real time allowed per student, compiling and running together
 * @param jobs how many students are graded at once (the results do not depend on it)
 * @param only re-grade only this student into the existing report in {@code out}, or null for all
 * @param lang the language of the reports and feedback: en or es
 * @param unsafe grade even where no isolation is available (every report then says so)
 * @param bwrap the bubblewrap program that isolates the submissions
 * @param packs teachers' assignment packs to load besides the kit's (folders or jars)
 * @param platform where the grade goes besides the reports
 * @param platformOut Gradescope's results folder, or the GitHub Actions output file (null: on
 *     standard output)
 * @param scratchRoot where scratch folders are made (the system's temporary folder by default)
 * @param clock what the reports' date is read from
 * @param version the JAria version the reports name
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
    Path bwrap,
    List<Path> packs,
    Platform platform,
    Path platformOut,
    Path scratchRoot,
    Clock clock,
    String version) {

  /** Real time per student unless asked otherwise. */
  public static final Duration DEFAULT_TIMEOUT = Duration.ofSeconds(60);

  /** Where bubblewrap is on Debian and Ubuntu. */
  public static final Path DEFAULT_BWRAP = Path.of("/usr/bin/bwrap");

  /** Copies the list. */
  public GradeRequest {
    packs = List.copyOf(packs);
  }

  /**
   * Grades all of {@code submissions} for {@code assignment} into {@code out}: one student at a
   * time, {@link #DEFAULT_TIMEOUT} each, in English, isolated by {@link #DEFAULT_BWRAP}.
   */
  public static GradeRequest of(String assignment, Path submissions, Path out) {
    return new GradeRequest(
        assignment,
        submissions,
        out,
        DEFAULT_TIMEOUT,
        1,
        null,
        "en",
        false,
        DEFAULT_BWRAP,
        List.of(),
        Platform.LOCAL,
        null,
        Path.of(System.getProperty("java.io.tmpdir")),
        Clock.systemUTC(),
        ClassGrading.version());
  }

  /** This request with {@code t} per student. */
  public GradeRequest withTimeout(Duration t) {
    return new GradeRequest(
        assignment,
        submissions,
        out,
        t,
        jobs,
        only,
        lang,
        unsafe,
        bwrap,
        packs,
        platform,
        platformOut,
        scratchRoot,
        clock,
        version);
  }

  /** This request grading {@code n} students at once. */
  public GradeRequest withJobs(int n) {
    return new GradeRequest(
        assignment,
        submissions,
        out,
        timeout,
        n,
        only,
        lang,
        unsafe,
        bwrap,
        packs,
        platform,
        platformOut,
        scratchRoot,
        clock,
        version);
  }

  /** This request re-grading only {@code student} into the existing report. */
  public GradeRequest onlyStudent(String student) {
    return new GradeRequest(
        assignment,
        submissions,
        out,
        timeout,
        jobs,
        student,
        lang,
        unsafe,
        bwrap,
        packs,
        platform,
        platformOut,
        scratchRoot,
        clock,
        version);
  }

  /** This request writing reports and feedback in {@code language} (en or es). */
  public GradeRequest inLanguage(String language) {
    return new GradeRequest(
        assignment,
        submissions,
        out,
        timeout,
        jobs,
        only,
        language,
        unsafe,
        bwrap,
        packs,
        platform,
        platformOut,
        scratchRoot,
        clock,
        version);
  }

  /** This request grading without isolation where none is available. */
  public GradeRequest withoutIsolation() {
    return new GradeRequest(
        assignment,
        submissions,
        out,
        timeout,
        jobs,
        only,
        lang,
        true,
        bwrap,
        packs,
        platform,
        platformOut,
        scratchRoot,
        clock,
        version);
  }

  /** This request isolating the submissions with the bubblewrap program at {@code program}. */
  public GradeRequest withBwrap(Path program) {
    return new GradeRequest(
        assignment,
        submissions,
        out,
        timeout,
        jobs,
        only,
        lang,
        unsafe,
        program,
        packs,
        platform,
        platformOut,
        scratchRoot,
        clock,
        version);
  }

  /** This request with the assignment packs {@code p} loaded besides the kit's. */
  public GradeRequest withPacks(List<Path> p) {
    return new GradeRequest(
        assignment,
        submissions,
        out,
        timeout,
        jobs,
        only,
        lang,
        unsafe,
        bwrap,
        p,
        platform,
        platformOut,
        scratchRoot,
        clock,
        version);
  }

  /** This request reporting to {@code p} too, its results going to {@code where}. */
  public GradeRequest reportingTo(Platform p, Path where) {
    return new GradeRequest(
        assignment,
        submissions,
        out,
        timeout,
        jobs,
        only,
        lang,
        unsafe,
        bwrap,
        packs,
        p,
        where,
        scratchRoot,
        clock,
        version);
  }

  /** This request making its scratch folders in {@code root}. */
  public GradeRequest withScratchRoot(Path root) {
    return new GradeRequest(
        assignment,
        submissions,
        out,
        timeout,
        jobs,
        only,
        lang,
        unsafe,
        bwrap,
        packs,
        platform,
        platformOut,
        root,
        clock,
        version);
  }

  /** This request dating its reports by {@code c}. */
  public GradeRequest withClock(Clock c) {
    return new GradeRequest(
        assignment,
        submissions,
        out,
        timeout,
        jobs,
        only,
        lang,
        unsafe,
        bwrap,
        packs,
        platform,
        platformOut,
        scratchRoot,
        c,
        version);
  }

  /** This request naming JAria version {@code v} in its reports. */
  public GradeRequest withVersion(String v) {
    return new GradeRequest(
        assignment,
        submissions,
        out,
        timeout,
        jobs,
        only,
        lang,
        unsafe,
        bwrap,
        packs,
        platform,
        platformOut,
        scratchRoot,
        clock,
        v);
  }
}
