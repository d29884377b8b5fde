package org.jaria.web.server;

import java.util.concurrent.atomic.LongAdder;

/** The server's counters (thread-safe), read as one {@link WebStats}. */
final class Counters {
  final LongAdder clientsServed = new LongAdder();
  final LongAdder clientsRefused = new LongAdder();
  final LongAdder malformed = new LongAdder();
  final LongAdder unknownOps = new LongAdder();
  final LongAdder oversized = new LongAdder();
  final LongAdder flooded = new LongAdder();
  final LongAdder refused = new LongAdder();
  final LongAdder controlCommands = new LongAdder();
  final LongAdder messagesSent = new LongAdder();
  final LongAdder bytesSent = new LongAdder();
  final LongAdder messagesDropped = new LongAdder();
  final LongAdder slowClientsClosed = new LongAdder();
  final LongAdder frames = new LongAdder();
  final LongAdder pagesServed = new LongAdder();
  final LongAdder notFound = new LongAdder();

  WebStats snapshot(int clientsNow) {
    return new WebStats(
        clientsNow,
        clientsServed.sum(),
        clientsRefused.sum(),
        malformed.sum(),
        unknownOps.sum(),
        oversized.sum(),
        flooded.sum(),
        refused.sum(),
        controlCommands.sum(),
        messagesSent.sum(),
        bytesSent.sum(),
        messagesDropped.sum(),
        slowClientsClosed.sum(),
        frames.sum(),
        pagesServed.sum(),
        notFound.sum());
  }
}
