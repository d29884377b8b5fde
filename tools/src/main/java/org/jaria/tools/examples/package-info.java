/**
 * The thesis's applications as ARIA programs (goto, gyro, chase, colour following), and its
 * path-following application (§6.1) headless: {@link org.jaria.tools.examples.NavigateDemo}. {@code
 * jaria demo} runs them.
 */
package org.jaria.tools.examples;
