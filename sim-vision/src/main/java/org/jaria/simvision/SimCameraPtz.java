package org.jaria.simvision;

import org.jaria.ptz.ArPTZ;
import org.jaria.sim.camera.SimCamera;

/**
 * Pan, tilt and zoom of a simulated camera through the PTZ interface a program uses for a real
 * Canon VC-C4, so vision programs run unchanged on the simulator. Same signs as every {@link
 * ArPTZ}: pan positive to the right.
 */
public final class SimCameraPtz extends ArPTZ {

  private final SimCamera camera;

  /** Controls {@code camera}. */
  public SimCameraPtz(SimCamera camera) {
    super(null);
    this.camera = camera;
  }

  @Override
  public boolean init() {
    camera.setPanTilt(0, 0);
    camera.setZoom(0);
    setCommanded(0, 0, 0);
    return true;
  }

  @Override
  public String getTypeName() {
    return "simulated";
  }

  @Override
  public double getMaxPan() {
    return 100;
  }

  @Override
  public double getMaxTilt() {
    return 90;
  }

  @Override
  public double getMaxNegTilt() {
    return -30;
  }

  @Override
  public int getMaxZoom() {
    return SimCamera.MAX_ZOOM;
  }

  @Override
  protected boolean panTiltClamped(double panDeg, double tiltDeg) {
    camera.setPanTilt(panDeg, tiltDeg);
    return true;
  }

  @Override
  protected boolean zoomClamped(int value) {
    camera.setZoom(value);
    return true;
  }

  /** Where the camera points, which may differ from the last request if something else moved it. */
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
}
