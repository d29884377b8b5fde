package org.jaria.net.client;

import com.google.errorprone.annotations.concurrent.GuardedBy;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.jaria.net.ArNetPacket;
import org.jaria.net.data.DataInfo;
import org.jaria.net.protocol.Protocol;

/**
 * The data list a server sent a client: names and command numbers, then the arguments and returns,
 * then groups and flags, each from its own list packet (at login, or later for one data). Thread
 * safe: the reader thread adds while user threads look up.
 */
final class DataList {

  @GuardedBy("this")
  private final Map<Integer, DataInfo> byCommand = new LinkedHashMap<>();

  @GuardedBy("this")
  private final Map<String, DataInfo> byName = new LinkedHashMap<>();

  synchronized void clear() {
    byCommand.clear();
    byName.clear();
  }

  /** Adds one list packet (any of the LIST commands); returns how many entries it had. */
  synchronized int add(ArNetPacket p) {
    int n = p.bufToUByte2();
    for (int i = 0; i < n; i++) {
      int cmd = p.bufToUByte2();
      String a = p.bufToStr();
      String b = p.bufToStr();
      DataInfo d = byCommand.get(cmd);
      switch (p.getCommand()) {
        case Protocol.SERVER_LIST, Protocol.SERVER_LIST_SINGLE ->
            d = new DataInfo(cmd, a, b, "", "", "", "");
        case Protocol.SERVER_LIST_ARGRET, Protocol.SERVER_LIST_ARGRET_SINGLE -> {
          if (d != null) {
            d = d.withArgRet(a, b);
          }
        }
        default -> {
          if (d != null) {
            d = d.withGroupAndFlags(a, b);
          }
        }
      }
      if (d != null) {
        byCommand.put(cmd, d);
        byName.put(d.name(), d);
      }
    }
    return n;
  }

  /** The data of command {@code cmd}, or null. */
  synchronized DataInfo get(int cmd) {
    return byCommand.get(cmd);
  }

  /** The data named {@code name}, or null. */
  synchronized DataInfo get(String name) {
    return byName.get(name);
  }

  synchronized boolean contains(String name) {
    return byName.containsKey(name);
  }

  synchronized int size() {
    return byName.size();
  }

  /** All data in command order. */
  synchronized List<DataInfo> list() {
    return List.copyOf(byCommand.values());
  }
}
