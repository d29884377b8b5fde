/**
 * The figures of localization and planning ({@code ./jaria bench arnl}): {@link
 * org.jaria.arnl.bench.ArnlBenchmark}.
 */
package org.jaria.arnl.bench;
