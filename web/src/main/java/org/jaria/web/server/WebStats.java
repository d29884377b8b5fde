package org.jaria.web.server;

/**
 * What the web server has done and refused, counted since it started.
 *
 * @param clients WebSocket clients connected now
 * @param clientsServed clients that ever connected
 * @param clientsRefused upgrades refused (too many clients, bad token, wrong subprotocol)
 * @param malformed client messages that were not messages of the protocol
 * @param unknownOps well-formed client messages with an unsupported operation
 * @param oversized connections closed for a message over the size limit
 * @param flooded client messages dropped unread because the client sent too fast
 * @param refused requests refused (no such channel, over a limit, read-only)
 * @param controlCommands control commands carried out
 * @param messagesSent messages sent to clients
 * @param bytesSent bytes sent to clients (WebSocket payloads)
 * @param messagesDropped messages not sent because the client's queue was full
 * @param slowClientsClosed clients disconnected for not reading
 * @param frames frames published
 * @param pagesServed static files served
 * @param notFound HTTP requests for anything else
 */
public record WebStats(
    int clients,
    long clientsServed,
    long clientsRefused,
    long malformed,
    long unknownOps,
    long oversized,
    long flooded,
    long refused,
    long controlCommands,
    long messagesSent,
    long bytesSent,
    long messagesDropped,
    long slowClientsClosed,
    long frames,
    long pagesServed,
    long notFound) {}
