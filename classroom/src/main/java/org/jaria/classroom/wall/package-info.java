/** Assignment 2: wall following with a custom action. */
package org.jaria.classroom.wall;
