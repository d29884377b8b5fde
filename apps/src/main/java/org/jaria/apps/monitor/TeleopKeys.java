package org.jaria.apps.monitor;

import java.util.EnumSet;
import java.util.Set;
import javafx.animation.KeyFrame;
import javafx.animation.Timeline;
import javafx.scene.input.KeyCode;
import javafx.scene.input.KeyEvent;
import javafx.util.Duration;

/**
 * Keyboard teleoperation, as MobileEyes drives: while an arrow key (or W A S D) is held, a {@code
 * ratioDrive} command goes to the server five times a second; releasing every key sends one with
 * zero ratios. The server's deadman stops the robot if commands stop arriving (a closed window, a
 * lost network). Space sends {@code stop}. JavaFX thread only.
 */
final class TeleopKeys {

  /** A command to send: translation and rotation ratios, −100..100, and the throttle 0..100. */
  interface Sender {
    void ratioDrive(double trans, double rot, double throttle);

    void stop();
  }

  private enum Dir {
    UP,
    DOWN,
    LEFT,
    RIGHT
  }

  private final Set<Dir> held = EnumSet.noneOf(Dir.class);
  private final Sender sender;
  private final Timeline repeat;
  private double throttle = 50;

  TeleopKeys(Sender sender) {
    this.sender = sender;
    repeat = new Timeline(new KeyFrame(Duration.millis(200), e -> send()));
    repeat.setCycleCount(Timeline.INDEFINITE);
  }

  /** Sets the throttle, 0..100 (the speed at full key). */
  void setThrottle(double t) {
    throttle = Math.max(0, Math.min(100, t));
  }

  double throttle() {
    return throttle;
  }

  /** Handles a key press; returns whether it was a driving key. */
  boolean pressed(KeyEvent e) {
    if (e.getCode() == KeyCode.SPACE) {
      held.clear();
      repeat.stop();
      sender.stop();
      return true;
    }
    Dir d = dir(e.getCode());
    if (d == null) {
      return false;
    }
    if (held.add(d)) {
      send();
      repeat.play();
    }
    return true;
  }

  /** Handles a key release; returns whether it was a driving key. */
  boolean released(KeyEvent e) {
    Dir d = dir(e.getCode());
    if (d == null) {
      return false;
    }
    held.remove(d);
    send();
    if (held.isEmpty()) {
      repeat.stop();
    }
    return true;
  }

  /** Forgets held keys (the window lost focus) and stops repeating. */
  void release() {
    if (!held.isEmpty()) {
      held.clear();
      send();
    }
    repeat.stop();
  }

  private void send() {
    double trans = (held.contains(Dir.UP) ? 100 : 0) - (held.contains(Dir.DOWN) ? 100 : 0);
    double rot = (held.contains(Dir.LEFT) ? 100 : 0) - (held.contains(Dir.RIGHT) ? 100 : 0);
    sender.ratioDrive(trans, rot, throttle);
  }

  private static Dir dir(KeyCode c) {
    return switch (c) {
      case UP, W -> Dir.UP;
      case DOWN, S -> Dir.DOWN;
      case LEFT, A -> Dir.LEFT;
      case RIGHT, D -> Dir.RIGHT;
      default -> null;
    };
  }
}
