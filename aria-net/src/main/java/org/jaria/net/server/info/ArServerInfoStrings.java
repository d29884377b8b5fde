package org.jaria.net.server.info;

import org.jaria.net.server.ArServerBase;
import org.jaria.net.server.PolledPublication;
import org.jaria.net.server.Where;

/**
 * Serves an {@link ArStringInfoGroup} (ArNetworking's {@code ArServerInfoStrings}): {@code
 * "getStrings"}, the values in order (published, evaluated on the publisher thread when a
 * subscription is due, sent only when a value changed), and {@code "getStringsInfo"}, their labels
 * and maximum lengths, both in ArNetworking's layouts.
 */
public final class ArServerInfoStrings {

  private final ArServerBase server;
  private final ArStringInfoGroup group;

  /**
   * Registers {@code "getStrings"} for {@code group}. {@code "getStringsInfo"} is registered by
   * {@link #addStringsInfo}, so that data numbers registered in between stay as they were.
   */
  public ArServerInfoStrings(ArServerBase server, ArStringInfoGroup group) {
    this.server = server;
    this.group = group;
    server.addPublishedData(
        "getStrings",
        "Gets the strings, for info about them see getStringsInfo",
        "repeating: string",
        "RobotInfo",
        PolledPublication.of(group::evaluate));
  }

  /** Registers {@code "getStringsInfo"}: the labels and maximum lengths of the strings. */
  public void addStringsInfo() {
    server.addData(
        "getStringsInfo",
        "Gets the information about the 'getStrings' command",
        "none",
        "uByte2: count; repeating count times  string: name, uByte2: maxlength",
        "RobotInfo",
        Where.WORKER,
        (client, request, reply) -> group.writeInfo(reply));
  }
}
