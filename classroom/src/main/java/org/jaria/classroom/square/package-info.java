/** Assignment 1: a square with motion commands. */
package org.jaria.classroom.square;
