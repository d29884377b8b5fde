package org.jaria.net.provider;

import org.jaria.geom.ArPose;
import org.jaria.net.data.LocalizationSnapshot;
import org.jaria.net.data.Particles;

/**
 * What the network server needs from a localizer (SonARNL's {@code ArSonarLocalizationTask} via an
 * adapter): its state, its particles, and relocalizing at a pose an operator gives.
 *
 * <p>Every method may be called from the server's threads (never the robot's cycle) and must be
 * thread-safe; the getters should be cheap (return the latest snapshot), since they are called at
 * the subscription rates.
 */
public interface LocalizationInfo {

  /** The current state, score and pose estimate. */
  LocalizationSnapshot getLocalizationState();

  /** The current particles ({@link Particles#NONE} if none); same update count, same particles. */
  Particles getParticles();

  /**
   * Relocalizes the robot at {@code pose} (an operator's "localize to pose"); may take a moment.
   *
   * @return whether the localizer accepted the pose
   */
  boolean localizeToPose(ArPose pose);
}
