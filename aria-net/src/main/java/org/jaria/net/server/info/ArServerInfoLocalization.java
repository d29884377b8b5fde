package org.jaria.net.server.info;

import org.jaria.net.data.LocState;
import org.jaria.net.provider.LocalizationInfo;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.PolledPublication;

/**
 * The localizer's state for clients (ARNL's {@code ArServerInfoLocalization}): {@code
 * "getLocState"} in ARNL's layout ({@link LocState}: state and score) and {@code "getLocPoints"}
 * (the particles, JAria's layout); with {@link #addLocalizationSnapshot}, JAria's {@code
 * "getLocalizationSnapshot"} (state, score, pose, samples, lost). All published, polled from the
 * {@link LocalizationInfo} on the publisher thread.
 */
public final class ArServerInfoLocalization {

  private final ArServerBase server;
  private final LocalizationInfo loc;

  /** Registers the localization data with {@code server}. */
  public ArServerInfoLocalization(ArServerBase server, LocalizationInfo loc) {
    this.server = server;
    this.loc = loc;
    server.addPublishedData(
        "getLocState",
        "gets the localization state",
        "ubyte: state (ARNL's LocalizationState); ubyte2: localization score 0..100",
        "LocalizationInfo",
        PolledPublication.of(() -> LocState.of(loc.getLocalizationState())));
    server.addPublishedData(
        "getLocPoints",
        "the localization's particles",
        "Particles [updateCount, [3, [x, y, th, ...]]]",
        "LocalizationInfo",
        PolledPublication.of(loc::getParticles));
  }

  /** Registers JAria's {@code "getLocalizationSnapshot"} (after the server's other data). */
  public void addLocalizationSnapshot() {
    server.addPublishedData(
        "getLocalizationSnapshot",
        "JAria: the localization's state, score, pose, samples and whether it is lost",
        "LocalizationSnapshot [state, score, pose [x, y, th] or nil, numSamples, lost]",
        "LocalizationInfo",
        PolledPublication.of(loc::getLocalizationState));
  }
}
