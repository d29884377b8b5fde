package org.jaria.mapping;

import java.util.Arrays;

/**
 * Counts per grid cell in an open-addressing hash table of primitive arrays: which cells of a fine
 * grid were hit, and how often, without a grid spanning the whole (possibly huge) map and without
 * an object per cell. Keys are cell coordinates packed into a long.
 *
 * <p>Not thread-safe.
 */
final class CellCounts {

  private static final long EMPTY = Long.MIN_VALUE;

  private long[] keys;
  private int[] counts;
  private int size;
  private int mask;

  CellCounts(int expected) {
    int cap = Integer.highestOneBit(Math.max(16, expected * 2 - 1)) << 1;
    keys = new long[cap];
    counts = new int[cap];
    Arrays.fill(keys, EMPTY);
    mask = cap - 1;
  }

  static long key(int cx, int cy) {
    return ((long) cx << 32) ^ (cy & 0xffffffffL);
  }

  static int keyX(long key) {
    return (int) (key >> 32);
  }

  static int keyY(long key) {
    return (int) key;
  }

  /** Adds {@code n} to the cell's count; returns the count before. */
  int add(int cx, int cy, int n) {
    long k = key(cx, cy);
    int i = slot(k);
    if (keys[i] == EMPTY) {
      keys[i] = k;
      counts[i] = n;
      if (++size * 2 > keys.length) {
        grow();
      }
      return 0;
    }
    int before = counts[i];
    counts[i] += n;
    return before;
  }

  /** The cell's count (0 if never hit). */
  int get(int cx, int cy) {
    long k = key(cx, cy);
    int i = slot(k);
    return keys[i] == EMPTY ? 0 : counts[i];
  }

  /** Number of cells hit. */
  int size() {
    return size;
  }

  /** Table capacity (for iterating with {@link #keyAt} and {@link #countAt}). */
  int capacity() {
    return keys.length;
  }

  /** Whether slot {@code i} holds a cell. */
  boolean used(int i) {
    return keys[i] != EMPTY;
  }

  long keyAt(int i) {
    return keys[i];
  }

  int countAt(int i) {
    return counts[i];
  }

  /** Approximate bytes held. */
  long bytes() {
    return 12L * keys.length + 32;
  }

  void clear() {
    Arrays.fill(keys, EMPTY);
    size = 0;
  }

  private int slot(long k) {
    int i = (int) mix(k) & mask;
    while (keys[i] != EMPTY && keys[i] != k) {
      i = (i + 1) & mask;
    }
    return i;
  }

  private static long mix(long k) {
    long h = k * 0x9E3779B97F4A7C15L;
    return h ^ (h >>> 29);
  }

  private void grow() {
    long[] oldKeys = keys;
    int[] oldCounts = counts;
    keys = new long[oldKeys.length * 2];
    counts = new int[oldKeys.length * 2];
    Arrays.fill(keys, EMPTY);
    mask = keys.length - 1;
    for (int i = 0; i < oldKeys.length; i++) {
      if (oldKeys[i] != EMPTY) {
        int s = slot(oldKeys[i]);
        keys[s] = oldKeys[i];
        counts[s] = oldCounts[i];
      }
    }
  }
}
