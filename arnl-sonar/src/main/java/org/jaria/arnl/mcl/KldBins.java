package org.jaria.arnl.mcl;

import java.util.Arrays;

/**
 * A small open-addressing hash table of 3-D integer bins with a weight each, reused between updates
 * so that counting occupied pose bins allocates nothing.
 */
final class KldBins {

  private static final long EMPTY = Long.MIN_VALUE;

  private final long[] keys;
  private final double[] weights;
  private final int mask;
  private int size;

  KldBins(int capacity) {
    int slots = Integer.highestOneBit(Math.max(16, capacity * 2 - 1)) << 1;
    keys = new long[slots];
    weights = new double[slots];
    mask = slots - 1;
    clear();
  }

  void clear() {
    Arrays.fill(keys, EMPTY);
    Arrays.fill(weights, 0);
    size = 0;
  }

  /** Bins in use. */
  int size() {
    return size;
  }

  /** Table slots (for iterating with {@link #used}). */
  int slots() {
    return keys.length;
  }

  boolean used(int slot) {
    return keys[slot] != EMPTY;
  }

  long keyX(int slot) {
    return keys[slot] >> 42;
  }

  long keyY(int slot) {
    return (keys[slot] << 22) >> 43;
  }

  void add(long i, long j, long k) {
    addWeight(i, j, k, 0);
  }

  void addWeight(long i, long j, long k, double weight) {
    long key = pack(i, j, k);
    int s = find(key);
    if (keys[s] == EMPTY) {
      if (size >= keys.length / 2) {
        // Table full enough: count in the last bin rather than degrade (never happens with the
        // sizes used, which are bounded by the particle count).
        return;
      }
      keys[s] = key;
      size++;
    }
    weights[s] += weight;
  }

  double weightOf(long i, long j, long k) {
    int s = find(pack(i, j, k));
    return keys[s] == EMPTY ? 0 : weights[s];
  }

  private int find(long key) {
    int s = (int) (mix(key) & mask);
    while (keys[s] != EMPTY && keys[s] != key) {
      s = (s + 1) & mask;
    }
    return s;
  }

  /** 22 bits for i, 21 for j, 21 for k (two's complement, so negative bins work). */
  private static long pack(long i, long j, long k) {
    return (i << 42) | ((j & 0x1FFFFFL) << 21) | (k & 0x1FFFFFL);
  }

  private static long mix(long v) {
    v ^= v >>> 33;
    v *= 0xff51afd7ed558ccdL;
    v ^= v >>> 33;
    return v;
  }
}
