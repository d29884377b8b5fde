package org.jaria.apps.fx;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * {@link Prompts} for windows nobody looks at ({@code jaria screenshot}): errors are collected (and
 * logged), questions are answered "no", file choosers are cancelled.
 */
public final class HeadlessPrompts implements Prompts {

  private static final Logger LOG = LoggerFactory.getLogger(HeadlessPrompts.class);
  private final List<String> errors = new ArrayList<>();

  /** The errors the app reported, as "title: message". */
  public synchronized List<String> errors() {
    return List.copyOf(errors);
  }

  @Override
  public synchronized void error(String title, String message) {
    LOG.warn("{}: {}", title, message);
    errors.add(title + ": " + message);
  }

  @Override
  public boolean confirm(String title, String question) {
    return false;
  }

  @Override
  public Optional<String> askText(String title, String prompt, String initial) {
    return Optional.empty();
  }

  @Override
  public Optional<Path> chooseOpenFile(String title, List<String> filters, Path initialDir) {
    return Optional.empty();
  }

  @Override
  public Optional<Path> chooseSaveFile(
      String title, List<String> filters, Path initialDir, String initialName) {
    return Optional.empty();
  }

  @Override
  public boolean confirmProblems(
      String title, String header, List<String> problems, String goOnLabel) {
    return false;
  }
}
