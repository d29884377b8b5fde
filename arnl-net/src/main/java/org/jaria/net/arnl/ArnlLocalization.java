package org.jaria.net.arnl;

import java.util.Objects;
import java.util.function.Supplier;
import org.jaria.arnl.ArSonarLocalizationTask;
import org.jaria.arnl.LocalizationState;
import org.jaria.geom.ArPose;
import org.jaria.net.data.LocalizationSnapshot;
import org.jaria.net.data.Particles;
import org.jaria.net.data.Points;
import org.jaria.net.provider.LocalizationInfo;

/**
 * Serves SonARNL's {@link ArSonarLocalizationTask} to monitors: its state, score and pose, its
 * particles, and relocalizing where an operator drops the robot on the map.
 */
public final class ArnlLocalization implements LocalizationInfo {

  private final Supplier<ArSonarLocalizationTask> current;

  /** Serves {@code loc}. */
  public ArnlLocalization(ArSonarLocalizationTask loc) {
    Objects.requireNonNull(loc, "loc");
    this.current = () -> loc;
  }

  /** Serves whichever task {@code current} gives (a new one after a map change). */
  ArnlLocalization(Supplier<ArSonarLocalizationTask> current) {
    this.current = current;
  }

  @Override
  public LocalizationSnapshot getLocalizationState() {
    ArSonarLocalizationTask loc = current.get();
    LocalizationState s = loc.getState();
    return new LocalizationSnapshot(
        s.name(),
        loc.getLocalizationScore(),
        loc.getInitializedFlag() ? loc.getCurrentLocaPose() : null,
        loc.getCurrentNumSamples(),
        loc.getRobotIsLostFlag());
  }

  @Override
  public Particles getParticles() {
    ArSonarLocalizationTask loc = current.get();
    return new Particles(loc.getUpdateCount(), Points.of(loc.getCurrentSamplePoses(), true));
  }

  /**
   * Localizes at {@code pose} with the configured spreads; if the sonar does not confirm it, the
   * pose is forced anyway (the operator knows where the robot is; tracking then corrects it).
   *
   * @return true: the pose is taken
   */
  @Override
  public boolean localizeToPose(ArPose pose) {
    ArSonarLocalizationTask loc = current.get();
    if (!loc.localizeRobotAtPose(pose)) {
      loc.forceUpdatePose(pose);
    }
    return true;
  }

  /** The task served. */
  public ArSonarLocalizationTask getTask() {
    return current.get();
  }
}
