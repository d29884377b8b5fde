package org.jaria.apps.fx;

import javafx.geometry.Point2D;
import javafx.scene.input.MouseButton;
import org.testfx.api.FxRobot;
import org.testfx.robot.MouseRobot;

/**
 * A user's mouse, quicker than TestFX's own moves: TestFX glides the pointer in up to 200 steps
 * with a pause each, which costs most of a UI test's time, while the apps only care where a press,
 * a drag and a release happen. Here the pointer jumps to where it clicks, and drags pass through a
 * few points on the way (every few pixels for a paint stroke, whose every pixel matters).
 */
public final class Mouse {

  private final FxRobot robot;
  private final MouseRobot mouse;

  /** The mouse of {@code robot}. */
  public Mouse(FxRobot robot) {
    this.robot = robot;
    this.mouse = robot.robotContext().getMouseRobot();
  }

  /** Puts the pointer at screen point {@code p}. */
  public Mouse moveTo(Point2D p) {
    mouse.move(p);
    return this;
  }

  /** Clicks the node a TestFX query names ("#step", "Load"), at its centre. */
  public Mouse click(String query) {
    return click(robot.point(query).query(), MouseButton.PRIMARY);
  }

  /** Clicks the centre of {@code node}. */
  public Mouse click(javafx.scene.Node node) {
    return click(robot.point(node).query(), MouseButton.PRIMARY);
  }

  /** Clicks {@code button} at screen point {@code p}. */
  public Mouse click(Point2D p, MouseButton button) {
    mouse.move(p);
    robot.clickOn(button);
    return this;
  }

  /** Double-clicks the primary button at {@code p}. */
  public Mouse doubleClick(Point2D p) {
    mouse.move(p);
    robot.doubleClickOn(MouseButton.PRIMARY);
    return this;
  }

  /** Drags with the primary button from {@code a} to {@code b} through 8 points on the way. */
  public Mouse drag(Point2D a, Point2D b) {
    return drag(a, b, 8);
  }

  /**
   * Drags with the primary button from {@code a} to {@code b} in steps of at most {@code
   * stepPixels} (a paint stroke that must touch every pixel on its way).
   */
  public Mouse stroke(Point2D a, Point2D b, double stepPixels) {
    return drag(a, b, (int) Math.ceil(a.distance(b) / stepPixels));
  }

  private Mouse drag(Point2D a, Point2D b, int steps) {
    mouse.move(a);
    mouse.press(MouseButton.PRIMARY);
    for (int i = 1; i < steps; i++) {
      mouse.moveNoWait(a.add(b.subtract(a).multiply((double) i / steps)));
    }
    mouse.move(b);
    mouse.release(MouseButton.PRIMARY);
    return this;
  }
}
