package org.jaria.net.server.info;

import org.jaria.net.provider.LocalizationInfo;
import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.PolledPublication;

/**
 * The localizer's state for clients (ArNetworking's {@code ArServerInfoLocalization}): {@code
 * "getLocState"} and {@code "getLocPoints"} (the particles), both published, polled from the {@link
 * LocalizationInfo} on the publisher thread.
 */
public final class ArServerInfoLocalization {

  /** Registers the localization data with {@code server}. */
  public ArServerInfoLocalization(ArServerBase server, LocalizationInfo loc) {
    server.addPublishedData(
        "getLocState",
        "the localization's state, score and pose",
        "LocalizationSnapshot [state, score, pose [x, y, th] or nil, numSamples, lost]",
        "LocalizationInfo",
        PolledPublication.of(loc::getLocalizationState));
    server.addPublishedData(
        "getLocPoints",
        "the localization's particles",
        "Particles [updateCount, [3, [x, y, th, ...]]]",
        "LocalizationInfo",
        PolledPublication.of(loc::getParticles));
  }
}
