package org.jaria.tools.guiserver.sim;

import java.util.Locale;
import java.util.Objects;
import org.jaria.acts.ptz.ArPTZ;
import org.jaria.net.provider.PtzControl;

/**
 * A pan-tilt-zoom unit of {@code org.jaria.acts.ptz} (an {@code ArVCC4} on the robot's AUX port,
 * say) as the guiServer's camera, so clients can point it with ArNetworking's camera requests. The
 * angles pass through unchanged: both follow ARIA's signs.
 */
public final class ActsPtz implements PtzControl {

  private final ArPTZ unit;

  /** Serves {@code unit}. */
  public ActsPtz(ArPTZ unit) {
    this.unit = Objects.requireNonNull(unit, "unit");
  }

  @Override
  public String getTypeName() {
    return unit.getTypeName().toUpperCase(Locale.ROOT);
  }

  @Override
  public boolean panTilt(double panDegrees, double tiltDegrees) {
    return unit.panTilt(panDegrees, tiltDegrees);
  }

  @Override
  public boolean zoom(int value) {
    return unit.canZoom() && unit.zoom(value);
  }

  @Override
  public double getPan() {
    return unit.getPan();
  }

  @Override
  public double getTilt() {
    return unit.getTilt();
  }

  @Override
  public int getZoom() {
    return unit.getZoom();
  }

  @Override
  public boolean canZoom() {
    return unit.canZoom();
  }

  @Override
  public double getMaxPosPan() {
    return unit.getMaxPosPan();
  }

  @Override
  public double getMaxNegPan() {
    return unit.getMaxNegPan();
  }

  @Override
  public double getMaxPosTilt() {
    return unit.getMaxPosTilt();
  }

  @Override
  public double getMaxNegTilt() {
    return unit.getMaxNegTilt();
  }

  @Override
  public int getMinZoom() {
    return unit.getMinZoom();
  }

  @Override
  public int getMaxZoom() {
    return unit.getMaxZoom();
  }

  @Override
  public boolean reset() {
    return unit.reset();
  }
}
