package org.jaria.net.server;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import org.jaria.net.data.DataInfo;
import org.jaria.net.protocol.Protocol;

/**
 * A server's data, numbered from 256 in the order they were registered (clients find them by name
 * and use the number on the wire). Registration is synchronized; lookups read thread-safe
 * collections.
 */
final class DataRegistry {

  private final List<DataEntry> entries = new CopyOnWriteArrayList<>();
  private final Map<String, DataEntry> byName = new ConcurrentHashMap<>();

  synchronized DataInfo register(
      String name,
      String description,
      String argDesc,
      String retDesc,
      String group,
      String flags,
      Where where,
      RequestHandler handler,
      Publication publication) {
    if (name == null || name.isEmpty()) {
      throw new IllegalArgumentException("data needs a name");
    }
    if (byName.containsKey(name)) {
      throw new IllegalArgumentException("data '" + name + "' is already registered");
    }
    if (entries.size() >= 0xFFFF - Protocol.FIRST_DATA_COMMAND) {
      throw new IllegalStateException("no command numbers left for '" + name + "'");
    }
    DataInfo info =
        new DataInfo(
            Protocol.FIRST_DATA_COMMAND + entries.size(),
            name,
            Objects.toString(description, ""),
            Objects.toString(argDesc, "none"),
            Objects.toString(retDesc, "none"),
            Objects.toString(group, ""),
            Objects.toString(flags, ""));
    DataEntry e = new DataEntry(info, where, handler, publication);
    entries.add(e);
    byName.put(name, e);
    return info;
  }

  /** Every registered data, in registration order. */
  List<DataInfo> dataList() {
    List<DataInfo> l = new ArrayList<>(entries.size());
    for (DataEntry e : entries) {
      l.add(e.info);
    }
    return l;
  }

  /** The data numbered {@code command}, or null. */
  DataEntry entry(int command) {
    List<DataEntry> l = entries;
    int i = command - Protocol.FIRST_DATA_COMMAND;
    return i >= 0 && i < l.size() ? l.get(i) : null;
  }

  /** The data named {@code name}, or null. */
  DataEntry byName(String name) {
    return byName.get(name);
  }
}
