package org.jaria.net.server.info;

import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.PolledPublication;

/**
 * Serves an {@link ArStringInfoGroup} as {@code "getStrings"} (ArNetworking's {@code
 * ArServerInfoStrings}): published, evaluated on the publisher thread when a subscription is due,
 * sent only when a value changed.
 */
public final class ArServerInfoStrings {

  /** Registers {@code "getStrings"} for {@code group}. */
  public ArServerInfoStrings(ArServerBase server, ArStringInfoGroup group) {
    server.addPublishedData(
        "getStrings",
        "the program's information table (label: value)",
        "InfoStrings [[label, value]...]",
        "RobotInfo",
        PolledPublication.of(group::evaluate));
  }
}
