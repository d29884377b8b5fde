/**
 * The figures of localization and planning ({@code ./jaria bench arnl}): {@link
 * org.jaria.tools.bench.arnl.ArnlBenchmark}.
 */
package org.jaria.tools.bench.arnl;
