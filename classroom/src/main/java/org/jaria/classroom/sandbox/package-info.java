/**
 * Containing a student's JVM with the operating system's isolation: what it may see, write and use,
 * and how its end is named (out of memory, too many threads, ...).
 */
package org.jaria.classroom.sandbox;
