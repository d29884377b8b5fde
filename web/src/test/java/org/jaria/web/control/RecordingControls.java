package org.jaria.web.control;

import java.util.ArrayList;
import java.util.List;
import org.jaria.geom.ArPose;

/** Controls that record what is asked of them (tests). */
public final class RecordingControls implements Controls.Driver, Controls.Simulation {
  public final List<String> calls = new ArrayList<>();
  public boolean acceptGoals = true;

  @Override
  public String robotName() {
    return "r";
  }

  @Override
  public void drive(double vel, double rotVel) {
    calls.add("drive " + vel + " " + rotVel);
  }

  @Override
  public boolean goTo(ArPose pose, boolean useHeading) {
    calls.add("goto " + pose);
    return acceptGoals;
  }

  @Override
  public void stop() {
    calls.add("stop");
  }

  @Override
  public void run() {
    calls.add("run");
  }

  @Override
  public void pause() {
    calls.add("pause");
  }

  @Override
  public void step(long millis) {
    calls.add("step " + millis);
  }

  @Override
  public void setSpeedup(double speedup) {
    calls.add("speed " + speedup);
  }
}
