/**
 * A teacher's whole grading run, as {@code jaria grade} asks for it: the request ({@link
 * org.jaria.classroom.classgrading.GradeRequest}, plain values) and its carrying out ({@link
 * org.jaria.classroom.classgrading.ClassGrading}): the packs loaded, the sandbox chosen, every
 * submission graded, the reports written and the grade handed to a platform. It sits on top of the
 * kit's other packages, and none of them names it.
 */
package org.jaria.classroom.classgrading;
