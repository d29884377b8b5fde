/**
 * A typed configuration registry (ARIA's {@code ArConfig}, thesis §5.1.30): modules register their
 * parameters — each with a type, bounds and a description — in named sections of an {@link
 * org.jaria.config.ArConfig}; the whole set is loaded from and saved to a text file in ARIA's
 * {@code .p} format, and modules hear about changes through callbacks.
 *
 * <pre>{@code
 * ArConfig config = new ArConfig();
 * ArConfigArg samples =
 *     config.addParam(
 *         ArConfigArg.ofInt("NumSamples", 2000, "particles in the filter", 10, 100000),
 *         "Localization");
 * config.addProcessFileCB(() -> { rebuild(); return true; }, 50);
 * config.parseFile(Path.of("params/arnl.p"));   // "file:line: ..." on a bad value
 * int n = samples.getInt();
 * }</pre>
 */
package org.jaria.config;
