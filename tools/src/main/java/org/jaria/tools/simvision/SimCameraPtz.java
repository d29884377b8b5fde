package org.jaria.tools.simvision;

import org.jaria.acts.ptz.ArPTZ;
import org.jaria.acts.ptz.PtzLimits;
import org.jaria.sim.camera.SimCamera;

/**
 * Pan, tilt and zoom of a simulated camera through the PTZ interface a program uses for a real
 * Canon VC-C4, so vision programs run unchanged on the simulator.
 */
public final class SimCameraPtz implements ArPTZ {

  private static final PtzLimits LIMITS = new PtzLimits(100, -100, 90, -30, SimCamera.MAX_ZOOM, 0);

  private final SimCamera camera;

  /** Controls {@code camera}. */
  public SimCameraPtz(SimCamera camera) {
    this.camera = camera;
  }

  @Override
  public boolean init() {
    camera.setPanTilt(0, 0);
    camera.setZoom(0);
    return true;
  }

  @Override
  public String getTypeName() {
    return "simulated";
  }

  @Override
  public boolean panTilt(double panDegrees, double tiltDegrees) {
    camera.setPanTilt(panDegrees, tiltDegrees);
    return true;
  }

  @Override
  public boolean canZoom() {
    return true;
  }

  @Override
  public boolean zoom(int value) {
    camera.setZoom(value);
    return true;
  }

  @Override
  public double getPan() {
    return camera.getPan();
  }

  @Override
  public double getTilt() {
    return camera.getTilt();
  }

  @Override
  public int getZoom() {
    return camera.getZoom();
  }

  @Override
  public PtzLimits getLimits() {
    return LIMITS;
  }
}
