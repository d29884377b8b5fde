package org.jaria.action;

import java.util.function.Consumer;

/** An action whose desire is set by the test, counting how often it fired. */
final class TestAction extends ArAction {

  private final ArActionDesired desired = new ArActionDesired();
  private final Consumer<ArActionDesired> setup;
  int fired;
  ArActionDesired lastShown;

  TestAction(String name, Consumer<ArActionDesired> setup) {
    super(name);
    this.setup = setup;
  }

  static TestAction vel(String name, double vel, double strength) {
    return new TestAction(name, d -> d.setVel(vel, strength));
  }

  @Override
  public ArActionDesired fire(ArActionDesired currentDesired) {
    fired++;
    lastShown = new ArActionDesired();
    lastShown.copyFrom(currentDesired);
    desired.reset();
    setup.accept(desired);
    return desired;
  }
}
