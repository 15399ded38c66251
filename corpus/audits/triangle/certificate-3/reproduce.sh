#!/bin/sh
lepp audit --engine triangle --method centroid --theta 20 --timeout 5 --inputs corpus/audits/triangle/certificate-3/input.poly
