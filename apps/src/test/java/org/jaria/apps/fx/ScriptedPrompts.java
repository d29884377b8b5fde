package org.jaria.apps.fx;

import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Optional;

/** {@link Prompts} for tests: answers from queues, remembers what it was told. */
public final class ScriptedPrompts implements Prompts {

  /** Error messages shown (title: message). */
  public final List<String> errors = new ArrayList<>();

  /** Problem lists shown before going on. */
  public final List<List<String>> problemLists = new ArrayList<>();

  /** Answers for {@link #askText}; empty queue = cancel. */
  public final Deque<String> texts = new ArrayDeque<>();

  /** Answers for the file choosers; empty queue = cancel. */
  public final Deque<Path> files = new ArrayDeque<>();

  /** Answer to every confirmation. */
  public volatile boolean confirmAnswer = true;

  /** Information shown (title: text), in order. */
  public final List<String> infos = new ArrayList<>();

  /** The questions asked for confirmation, in order. */
  public final List<String> confirms = new ArrayList<>();

  @Override
  public synchronized void error(String title, String message) {
    errors.add(title + ": " + message);
  }

  @Override
  public synchronized void info(String title, String text) {
    infos.add(title + ": " + text);
  }

  @Override
  public synchronized boolean confirm(String title, String question) {
    confirms.add(question);
    return confirmAnswer;
  }

  @Override
  public synchronized Optional<String> askText(String title, String prompt, String initial) {
    return Optional.ofNullable(texts.poll());
  }

  @Override
  public synchronized Optional<Path> chooseOpenFile(
      String title, List<String> filters, Path initialDir) {
    return Optional.ofNullable(files.poll());
  }

  @Override
  public synchronized Optional<Path> chooseSaveFile(
      String title, List<String> filters, Path initialDir, String initialName) {
    return Optional.ofNullable(files.poll());
  }

  @Override
  public synchronized boolean confirmProblems(
      String title, String header, List<String> problems, String goOnLabel) {
    problemLists.add(List.copyOf(problems));
    return confirmAnswer;
  }
}
