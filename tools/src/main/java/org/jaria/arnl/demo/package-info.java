/**
 * The thesis's path-following application (§6.1), headless: {@link
 * org.jaria.arnl.demo.NavigateDemo}.
 */
package org.jaria.arnl.demo;
