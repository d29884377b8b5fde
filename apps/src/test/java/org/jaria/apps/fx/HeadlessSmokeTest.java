package org.jaria.apps.fx;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.concurrent.atomic.AtomicInteger;
import javafx.scene.Scene;
import javafx.scene.control.Button;
import javafx.stage.Stage;
import org.junit.jupiter.api.Tag;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.testfx.api.FxRobot;
import org.testfx.framework.junit5.ApplicationExtension;
import org.testfx.framework.junit5.Start;

/** JavaFX, TestFX and Monocle work together headless: a click reaches a button. */
@Tag("gui")
@ExtendWith(ApplicationExtension.class)
class HeadlessSmokeTest {

  private final AtomicInteger clicks = new AtomicInteger();

  @Start
  void start(Stage stage) {
    Button b = new Button("press me");
    b.setId("b");
    b.setOnAction(e -> clicks.incrementAndGet());
    stage.setScene(new Scene(b, 200, 100));
    stage.show();
  }

  @Test
  void clickReachesButton(FxRobot robot) {
    robot.clickOn("#b");
    assertEquals(1, clicks.get());
  }
}
